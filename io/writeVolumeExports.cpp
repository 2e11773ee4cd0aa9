#include "io/writeVolumeExports.h"

#include <cmath>
#include <cstdint>
#include <filesystem>

#include "common/srgb.h"
#include "io/writeNpy.h"
#include "io/writeVti.h"

namespace solidtex {
namespace {

// Fiji shows 8-bit RGB stacks as colour; the exact linear values are in the .npy and .vti files.
std::vector<std::uint8_t> srgbBytes(const std::vector<Rgb>& color) {
  std::vector<std::uint8_t> bytes(color.size() * 3);
  for (std::size_t i = 0; i < color.size(); ++i)
    for (int c = 0; c < 3; ++c) bytes[3 * i + c] = std::uint8_t(std::lround(255 * linearToSrgb(color[i][c])));
  return bytes;
}

std::string inFolder(const std::string& folder, const std::string& name) {
  return (std::filesystem::path(folder) / name).string();
}

void writeTiffs(OutputFiles& outputs, const std::string& folder, const SolidVolume& volume,
                const VoxelSize& voxelSize, std::vector<std::string>& written) {
  auto write = [&](const std::string& name, int channels, StackSample sample, const void* data) {
    const std::string path = inFolder(folder, name);
    outputs.write(path, [&](const std::string& file) {
      writeTiffStack(file, volume.dims, channels, sample, data, voxelSize);
    });
    written.push_back(path);
  };
  if (!volume.color.empty()) write("color.tif", 3, StackSample::UInt8, srgbBytes(volume.color).data());
  if (!volume.particleId.empty()) write("particle_id.tif", 1, StackSample::Int32, volume.particleId.data());
  if (const std::vector<std::uint8_t> phase = phaseGrid(volume); !phase.empty())
    write("phase.tif", 1, StackSample::UInt8, phase.data());
  if (!volume.density.empty()) write("density.tif", 1, StackSample::Float32, volume.density.data());
}

void writeNpys(OutputFiles& outputs, const std::string& folder, const SolidVolume& volume,
               std::vector<std::string>& written) {
  const Dims& d = volume.dims;
  const std::vector<std::size_t> zyx{std::size_t(d.z), std::size_t(d.y), std::size_t(d.x)};
  auto write = [&](const std::string& name, const std::string& descr, std::vector<std::size_t> shape,
                   const void* data, std::size_t itemBytes = 4) {
    const std::string path = inFolder(folder, name);
    outputs.write(path, [&](const std::string& file) { writeNpy(file, descr, shape, data, itemBytes); });
    written.push_back(path);
  };
  if (!volume.color.empty()) write("color.npy", "<f4", {zyx[0], zyx[1], zyx[2], 3}, volume.color.data());
  if (!volume.particleId.empty()) write("particle_id.npy", "<i4", zyx, volume.particleId.data());
  if (const std::vector<std::uint8_t> phase = phaseGrid(volume); !phase.empty())
    write("phase.npy", "|u1", zyx, phase.data(), 1);
  if (!volume.density.empty()) write("density.npy", "<f4", zyx, volume.density.data());
}

std::vector<VtiArray> vtiArrays(const SolidVolume& volume, const std::vector<std::uint8_t>& phase) {
  std::vector<VtiArray> arrays;
  if (!volume.color.empty()) arrays.push_back({"color", "Float32", 3, 4, volume.color.data()});
  if (!volume.particleId.empty()) arrays.push_back({"particle_id", "Int32", 1, 4, volume.particleId.data()});
  if (!phase.empty()) arrays.push_back({"phase", "UInt8", 1, 1, phase.data()});
  if (!volume.density.empty()) arrays.push_back({"density", "Float32", 1, 4, volume.density.data()});
  return arrays;
}

}  // namespace

void addVolumeExports(OutputFiles& outputs, const VolumeExports& exports) {
  if (exports.tiff) outputs.addFolder("--tiff", *exports.tiff);
  if (exports.npy) outputs.addFolder("--npy", *exports.npy);
  if (exports.vti) outputs.addFile("--vti", *exports.vti, {".vti"});
}

std::vector<std::string> writeVolumeExports(OutputFiles& outputs, const VolumeExports& exports,
                                            const SolidVolume& volume, const VoxelSize& voxelSize) {
  std::vector<std::string> written;
  if (exports.tiff) writeTiffs(outputs, *exports.tiff, volume, voxelSize, written);
  if (exports.npy) writeNpys(outputs, *exports.npy, volume, written);
  if (exports.vti) {
    outputs.write(*exports.vti, [&](const std::string& file) {
      writeVti(file, volume.dims, volume.origin, 1,
               vtiArrays(volume, phaseGrid(volume)));  // the .vdb's own voxel units
    });
    written.push_back(*exports.vti);
  }
  return written;
}

}  // namespace solidtex

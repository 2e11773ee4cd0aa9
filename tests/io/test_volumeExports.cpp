#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "common/srgb.h"
#include "io/writeNpy.h"
#include "io/writeVolumeExports.h"
#include "tests/scratchPath.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

// Every voxel different: a transposed axis or a shifted slice shows.
SolidVolume gradientVolume() {
  SolidVolume v;
  v.dims = {7, 5, 3};
  for (int k = 0; k < v.dims.z; ++k)
    for (int j = 0; j < v.dims.y; ++j)
      for (int i = 0; i < v.dims.x; ++i) {
        v.color.push_back({i / 6.f, j / 4.f, k / 2.f});
        v.particleId.push_back(std::int32_t(v.dims.index(i, j, k)) - 3);
        v.density.push_back(0.01f * float(v.dims.index(i, j, k)));
      }
  v.origin = {2, 0, 1};
  return v;
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Written {
  fs::path folder;
  SolidVolume volume = gradientVolume();
  Written() : folder(test::scratchPath("exports", std::to_string(::getpid()))) {
    fs::remove_all(folder);
    VolumeExports exports{(folder / "tif").string(), (folder / "npy").string(), (folder / "v.vti").string()};
    OutputFiles outputs;
    addVolumeExports(outputs, exports);
    writeVolumeExports(outputs, exports, volume, {2.5, "pixel"});
    outputs.commit();
  }
  ~Written() { fs::remove_all(folder); }
};

template <typename T>
std::vector<T> tiffPages(const fs::path& path, int channels, OIIO::TypeDesc type, int& pages,
                         float& resolution) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << OIIO::geterror();
  std::vector<T> values;
  for (pages = 0; in && in->seek_subimage(pages, 0); ++pages) {
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.nchannels, channels);
    resolution = spec.get_float_attribute("XResolution");
    std::vector<T> page(std::size_t(spec.width) * spec.height * channels);
    EXPECT_TRUE(in->read_image(pages, 0, 0, channels, type, page.data()));
    values.insert(values.end(), page.begin(), page.end());
  }
  return values;
}

TEST(VolumeExports, TiffStacksReadBackAsTheVolume) {
  const Written w;
  int pages = 0;
  float resolution = 0;
  const auto ids =
      tiffPages<std::int32_t>(w.folder / "tif/particle_id.tif", 1, OIIO::TypeDesc::INT32, pages, resolution);
  EXPECT_EQ(pages, w.volume.dims.z);
  EXPECT_EQ(ids, w.volume.particleId);
  EXPECT_FLOAT_EQ(resolution, 1 / 2.5f);  // pixels per unit: Fiji's calibration
  const auto density =
      tiffPages<float>(w.folder / "tif/density.tif", 1, OIIO::TypeDesc::FLOAT, pages, resolution);
  EXPECT_EQ(density, w.volume.density);
  const auto srgb =
      tiffPages<std::uint8_t>(w.folder / "tif/color.tif", 3, OIIO::TypeDesc::UINT8, pages, resolution);
  ASSERT_EQ(srgb.size(), 3 * w.volume.dims.count());
  for (std::size_t i = 0; i < w.volume.color.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(srgb[3 * i + c], std::lround(255 * linearToSrgb(w.volume.color[i][c]))) << i;
}

TEST(VolumeExports, NpyFilesHoldTheVolumeInZYXOrder) {
  const Written w;
  const std::string color = fileBytes(w.folder / "npy/color.npy");
  const std::string header = npyHeader("<f4", {3, 5, 7, 3});
  EXPECT_EQ(header.size() % 64, 0u);
  EXPECT_NE(header.find("'shape': (3, 5, 7, 3)"), std::string::npos);
  ASSERT_EQ(color.size(), header.size() + w.volume.color.size() * 12);
  EXPECT_EQ(color.substr(0, header.size()), header);
  EXPECT_EQ(std::memcmp(color.data() + header.size(), w.volume.color.data(), w.volume.color.size() * 12), 0);
  const std::string ids = fileBytes(w.folder / "npy/particle_id.npy");
  EXPECT_NE(ids.find("'descr': '<i4'"), std::string::npos);
  EXPECT_NE(ids.find("'shape': (3, 5, 7)"), std::string::npos);
  EXPECT_NE(npyHeader("<i4", {4}).find("'shape': (4,), }"), std::string::npos);
}

TEST(VolumeExports, VtiPlacesCellsWhereTheVdbPutsVoxels) {
  const Written w;
  const std::string vti = fileBytes(w.folder / "v.vti");
  EXPECT_NE(vti.find("WholeExtent=\"0 7 0 5 0 3\""), std::string::npos);
  // In the .vdb's units: voxel (0,0,0) of a volume whose origin is (2,0,1) is centred at (2,0,1),
  // its cell's corner half a voxel below, whatever the stacks' physical voxel size.
  EXPECT_NE(vti.find("Origin=\"1.5 -0.5 0.5\""), std::string::npos);
  EXPECT_NE(vti.find("Spacing=\"1 1 1\""), std::string::npos);
  const std::size_t start = vti.find('_', vti.find("<AppendedData")) + 1;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, vti.data() + start, 8);
  ASSERT_EQ(bytes, w.volume.color.size() * 12);
  EXPECT_EQ(std::memcmp(vti.data() + start + 8, w.volume.color.data(), bytes), 0);
  const std::size_t ids = start + 8 + bytes;
  std::memcpy(&bytes, vti.data() + ids, 8);
  ASSERT_EQ(bytes, w.volume.particleId.size() * 4);
  EXPECT_EQ(std::memcmp(vti.data() + ids + 8, w.volume.particleId.data(), bytes), 0);
  EXPECT_NE(vti.find("offset=\"" + std::to_string(8 + w.volume.color.size() * 12) + "\""), std::string::npos);
}

}  // namespace
}  // namespace solidtex

#include "io/writeTiffStack.h"

#include <vector>

#include <OpenImageIO/imageio.h>
#include <tiffio.h>

#include "common/Error.h"
#include "io/detail/CapturedStderr.h"

namespace solidtex {
namespace {

OIIO::TypeDesc typeOf(StackSample sample) {
  switch (sample) {
    case StackSample::UInt8:
      return OIIO::TypeDesc::UINT8;
    case StackSample::Int32:
      return OIIO::TypeDesc::INT32;
    case StackSample::Float32:
      return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::UNKNOWN;
}

OIIO::ImageSpec pageSpec(const Dims& dims, int channels, StackSample sample, const VoxelSize& voxelSize) {
  OIIO::ImageSpec spec(dims.x, dims.y, channels, typeOf(sample));
  spec.attribute("compression", "none");
  // Classic TIFF's offsets end at 4 GiB: a larger stack (1024^3 ids) is BigTIFF, which Fiji opens
  // through Bio-Formats.
  const double bytes = double(dims.count()) * channels * double(typeOf(sample).size());
  if (bytes > 3.5 * (1u << 30)) spec.attribute("tiff:bigtiff", 1);
  spec.attribute("ImageDescription", "solidtex volume: " + std::to_string(dims.z) +
                                         " slices, isotropic voxels of " + std::to_string(voxelSize.size) +
                                         " " + voxelSize.unit);
  spec.attribute("Software", "solidtex");
  // Left to OpenImageIO, DateTime holds the wall clock, and two runs of one command differ in bytes.
  spec.attribute("DateTime", "");
  return spec;
}

// OpenImageIO 2.4 writes resolutions under one pixel per unit as 1, so libtiff sets them on every
// page: pixels per unit, which Fiji reads as the calibration. Reading every page back also checks
// that the file is whole, which OpenImageIO's own file writing does not report.
void setResolution(const std::string& path, int pages, const VoxelSize& voxelSize) {
  TIFF* tiff = TIFFOpen(path.c_str(), "r+");
  if (!tiff) throw InputError("cannot write " + path + ": the TIFF written cannot be read back");
  bool ok = true;
  const auto pixelsPerUnit = float(1 / voxelSize.size);
  int page = 0;
  for (; ok && page < pages && TIFFSetDirectory(tiff, tdir_t(page)); ++page)
    ok = TIFFSetField(tiff, TIFFTAG_RESOLUTIONUNIT, RESUNIT_NONE) &&
         TIFFSetField(tiff, TIFFTAG_XRESOLUTION, pixelsPerUnit) &&
         TIFFSetField(tiff, TIFFTAG_YRESOLUTION, pixelsPerUnit) && TIFFRewriteDirectory(tiff);
  TIFFClose(tiff);
  if (!ok || page != pages)
    throw InputError("cannot write " + path + ": the TIFF written is incomplete (is the disk full?)");
}

}  // namespace

void writeTiffStack(const std::string& path, const Dims& dims, int channels, StackSample sample,
                    const void* data, const VoxelSize& voxelSize) {
  auto out = OIIO::ImageOutput::create("tiff");
  if (!out) throw InputError("cannot write " + path + ": no TIFF writer available");
  const std::vector<OIIO::ImageSpec> pages(std::size_t(dims.z), pageSpec(dims, channels, sample, voxelSize));
  const std::size_t pageBytes = std::size_t(dims.x) * dims.y * channels * typeOf(sample).size();
  io::detail::CapturedStderr libraryOutput;  // libtiff prints its warnings and errors
  bool ok = out->open(path, int(pages.size()), pages.data());
  for (int z = 0; ok && z < dims.z; ++z) {
    if (z > 0) ok = out->open(path, pages[std::size_t(z)], OIIO::ImageOutput::AppendSubimage);
    ok = ok && out->write_image(typeOf(sample), static_cast<const char*>(data) + z * pageBytes);
  }
  ok = out->close() && ok;
  if (!ok) throw InputError("cannot write " + path + ": " + out->geterror());
  setResolution(path, dims.z, voxelSize);
}

}  // namespace solidtex

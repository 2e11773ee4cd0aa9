// loadMask on a file and a photo size: the first 4 bytes are the photo's width and height (two
// little-endian 16-bit numbers), the rest is the mask file. Only InputError may escape loadMask.
#include <cstddef>
#include <cstdint>

#include "common/Error.h"
#include "imageLimit.h"
#include "inputFile.h"
#include "segmentation/detail/loadMask.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 4) return 0;
  const cv::Size photoSize(data[0] | data[1] << 8, data[2] | data[3] << 8);
  static solidtex::fuzz::InputFile file("mask.png");
  const std::string& path = file.write(data + 4, size - 4);
  if (solidtex::fuzz::tooLargeToFuzz(path)) return 0;
  try {
    const cv::Mat mask = solidtex::segmentation::detail::loadMask(path, photoSize);
    // The promise callers rely on: one byte per pixel, at the photo's size.
    if (mask.type() != CV_8U || mask.size() != photoSize) __builtin_trap();
  } catch (const solidtex::InputError&) {
  }
  return 0;
}

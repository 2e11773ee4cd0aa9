#pragma once
#include <algorithm>
#include <string>

#include <OpenImageIO/imageio.h>

namespace solidtex::fuzz {

/// loadPhoto accepts up to 20000x20000 pixels, and a few-byte header can claim that many: decoding
/// and analysing cost grows with the pixel count, and under the sanitizers the fuzzer would spend
/// its time on a few huge images. Harnesses skip images larger than this (read from the header,
/// as loadPhoto does), so that executions stay short and within libFuzzer's memory limit.
inline constexpr long kMaxFuzzPixels = 512L * 512L;

/// True when OpenImageIO reads a header claiming more than kMaxFuzzPixels pixels; false also when
/// it cannot read one (loadPhoto should then refuse the file, which is what the harness checks).
inline bool tooLargeToFuzz(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    OIIO::geterror();  // clears OpenImageIO's per-thread message so that it does not pile up
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  return long(spec.width) * spec.height * std::max(spec.depth, 1) > kMaxFuzzPixels;
}

}  // namespace solidtex::fuzz

// Photo bytes -> loadPhoto -> analyzeExemplar with default options. A clean refusal (InputError) is
// the expected outcome for broken files; any other exception, crash or sanitizer report is a finding.
#include <cstddef>
#include <cstdint>

#include "common/Error.h"
#include "imageLimit.h"
#include "inputFile.h"
#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static solidtex::fuzz::InputFile file("photo.png");
  const std::string& path = file.write(data, size);
  if (solidtex::fuzz::tooLargeToFuzz(path)) return 0;
  try {
    const cv::Mat photo = solidtex::loadPhoto(path);
    solidtex::analyzeExemplar(photo, "fuzz", solidtex::SegmentationOptions{});
  } catch (const solidtex::InputError&) {
  }
  return 0;
}

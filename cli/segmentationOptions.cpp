#include "cli/commands.h"
#include "cli/optionChecks.h"
#include "io/imageIO.h"

namespace solidtex::cli {

void addSegmentationOptions(CLI::App& command, SegmentationOptions& options) {
  command.add_option("--mask", options.maskPath,
                     "Mask image (white = particle) used instead of automatic segmentation");
  command.add_flag("--invert", options.invert, "Swap which class the automatic segmentation calls particle");
  command.add_flag("!--no-split", options.split, "Do not split touching particles");
  command
      .add_option_function<std::string>(
          "--outlines", [&options](const std::string& name) { options.outlines = parseOutlineMethod(name); },
          "How the automatic segmentation draws outlines: watershed (where the floods from both sides meet), "
          "half-maximum (half-way up each particle's smoothed edge: blurred photos), or auto (half-maximum "
          "when the outlines look blurred by a pixel or more on a plain background; the default)")
      ->check(CLI::IsMember({"auto", "watershed", "half-maximum"}))
      ->type_name("METHOD");
  command
      .add_option("--min-area", options.minArea,
                  "Drop particles smaller than this many pixels (default: the photo's, from its size and the "
                  "sizes of its regions)")
      ->check(between(0, double(kMaxPhotoSide) * kMaxPhotoSide));
}

}  // namespace solidtex::cli

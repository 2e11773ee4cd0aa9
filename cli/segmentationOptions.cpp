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

namespace {

// 1 to 8, or 0 for "auto"; -1 for anything else.
int phaseCount(const std::string& value) {
  if (value == "auto") return kAutoPhases;
  std::size_t used = 0;
  int count = -1;
  try {
    count = std::stoi(value, &used);
  } catch (const std::exception&) {
    return -1;
  }
  return used == value.size() && count >= 1 && count <= kMaxPhases ? count : -1;
}

}  // namespace

void addPhaseOptions(CLI::App& command, PhaseOptions& options) {
  command
      .add_option_function<std::string>(
          "--phases", [&options](const std::string& value) { options.phases = phaseCount(value); },
          "Kinds of particle, sorted by colour and grain (k-means in CIE L*a*b* and grain contrast): a "
          "count from 1 to 8, or auto (the count the BIC chooses); each kind gets its own sizes, shapes, "
          "colours and share, and the solid a phase grid")
      ->check(CLI::Validator(
          [](std::string& value) {
            return phaseCount(value) < 0 ? "must be auto or a count from 1 to 8, got " + value
                                         : std::string();
          },
          ""))
      ->type_name("K|auto");
  command.add_option("--phase-mask", options.maskPath,
                     "An image of the photo's phases, one per distinct value: each particle takes the value "
                     "under most of it (at most --phases of them)");
}

}  // namespace solidtex::cli

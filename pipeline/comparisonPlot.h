#pragma once
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

namespace solidtex {

/// A pointwise band of the 3D particle-volume CDF (the particles' sizing: 5 % and 95 % of its
/// bootstrap), at log-spaced volumes in photo pixels cubed.
struct VolumeCdfBand {
  std::vector<double> volumes, low, high;
};

/// What the comparison plot shows.
struct ComparisonData {
  std::vector<double> photoAreas;        ///< voxel^2
  std::vector<double> sectionAreas;      ///< voxel^2
  std::array<double, 10> areaHistogram;  ///< ratios
  std::array<double, 10> volumeHistogram;
  std::vector<double> photoSolidity;  ///< of the photo's particles at the solid's resolution
  std::vector<double> sectionSolidity;
  std::string volumeLabel = "solid volumes";       ///< what the volumes are a sample of, in short
  VolumeCdfBand volumeBand;                        ///< none: no panel of 3D volumes
  std::vector<double> solidVolumes, truthVolumes;  ///< photo pixels^3; the truth's when compared with one
};

/// Ratios of values in 10 equal-width bins between their min and max (the paper's Fig. 9/10 binning).
std::array<double, 10> tenBinRatios(const std::vector<double>& values);

/// A chart a person reads at a glance: the photo's area histogram beside the volume's volume
/// histogram, the CDFs of section and photo areas and of their solidity, with the report's numbers.
cv::Mat plotComparison(const ComparisonData& data, const nlohmann::json& report);

}  // namespace solidtex

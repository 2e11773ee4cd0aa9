#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// How the 3D particles are sized from the photo.
enum class Sizing {
  Bbox,      ///< the paper's: a photo (w,h) pair by its frequency in the photo
  Sections,  ///< photo particles reweighted and enlarged so that random sections of the solid match the
             ///< photo's areas
};

/// "bbox" | "sections"; throws InputError otherwise.
Sizing parseSizing(const std::string& name);
const char* sizingName(Sizing sizing);

/// The photo's particles in size classes evenly spaced in log area: the resolution of the unfolding,
/// finer than the 10-bin histogram where most particles are (its first bin often holds half).
struct AreaClasses {
  std::vector<double> edges;  ///< class c covers [edges[c], edges[c+1]); the last includes its upper edge
  std::vector<int> classOf;   ///< per ExemplarStats::particles index; -1 for the ones statistics leave out
  int count() const { return int(edges.size()) - 1; }
  /// Class of an area; -1 below the first edge, the last class above the last edge.
  int classOfArea(double area) const;
};

/// Classes from half the smallest area of the particles the histogram counts (not below the photo's
/// smallest kept area) to the largest.
AreaClasses areaClassesOf(const ExemplarStats& stats, int classes = 16);

/// One random plane through one particle made for a class, at size factor 1, in photo pixels.
struct SectionSample {
  int particleClass = 0;
  double area = 0;    ///< pixels^2; 0 when the plane missed every voxel centre
  double width = 0;   ///< pixels: the particle's extent along the plane's normal (how likely a plane cuts it)
  double volume = 0;  ///< pixels^3 of the particle cut
};

/// Random sections of factory particles made for each class, `shapesPerClass` shapes cut by
/// `planesPerShape` planes each, measured on shapes whose largest box side is at most 64 voxels
/// (enough to resolve the areas, whatever the volume's size). Parallel, the same at any thread count.
std::vector<SectionSample> sampleParticleSections(const ExemplarStats& stats, const ParticleFactory& factory,
                                                  const AreaClasses& classes, double voxelsPerPixel,
                                                  std::uint64_t seed, int shapesPerClass = 32,
                                                  int planesPerShape = 64);

/// Column j: sections per class-j particle and per pixel of plane spacing that fall in each class,
/// with every particle `sizeFactor` times larger than sampled (areas times its square, widths
/// times it); sections below `minArea` are lost as the photo's specks are.
Eigen::MatrixXd sectionKernel(const std::vector<SectionSample>& samples, const AreaClasses& classes,
                              double minArea, double sizeFactor);

/// Stereological unfolding by EMS (Silverman et al.'s smoothed expectation-maximisation): the
/// non-negative 3D class shares x, summing to 1, whose sections `kernel * x` reproduce the observed
/// section shares. The smoothing step keeps the photo's counting noise out of x; columns of zeros
/// (classes nothing was made for) get share 0.
Eigen::VectorXd unfoldSections(const Eigen::MatrixXd& kernel, const Eigen::VectorXd& observed,
                               int iterations = 200);

/// How much the 3D sizes depend on which particles the photo happened to show: the fit redone on
/// bootstrap resamples of the photo's particles. A photo of a few dozen particles decides little.
struct SizingUncertainty {
  int bootstraps = 0;
  double sizeFactorLow = 1,
         sizeFactorHigh = 1;  ///< 5th and 95th percentile of the size factor (the range, for few)
  double meanVolumeSpread =
      0;  ///< root mean square of their mean particle volume less the fit's, / the fit's
  /// The 3D particle-volume CDF the fit implies (its class shares over the volumes of the shapes made
  /// for each class, at its size factor) at `bandVolumes` (photo pixels cubed, log-spaced), with the
  /// 5th and 95th percentiles of the resamples' CDFs there.
  std::vector<double> bandVolumes, bandCdf, bandLow, bandHigh;
};

/// Particle sizes whose random sections reproduce the photo's areas.
struct SectionSizing {
  double sizeFactor = 1;                ///< 3D boxes are this many times the photo's (w,h) and depth
  std::vector<double> particleWeights;  ///< per ExemplarStats::particles index: its share of the 3D particles
  std::array<double, 10> binRatios{};   ///< the same shares summed per area-histogram bin
  double predictedKs = 0;               ///< KS of the predicted section areas against the photo's
  SizingUncertainty uncertainty;
};

/// Unfolds the photo's section areas at size factors 1 to 2 and keeps the smallest factor whose
/// predicted sections are about as close (KS, within the photo's counting noise) to the photo's as
/// the best one's: a plane rarely cuts a particle through its largest section, so the particles must
/// be larger than their sections, by more when the photo's sizes are narrowly spread. With
/// `bootstraps` > 0, also how uncertain that is (the fit redone on that many resamples).
SectionSizing fitSectionSizing(const ExemplarStats& stats, const ParticleFactory& factory,
                               double voxelsPerPixel, std::uint64_t seed, int bootstraps = 0);

}  // namespace solidtex

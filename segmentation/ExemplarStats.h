#pragma once
#include <array>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace solidtex {

/// One particle of the photo, as segmentation found it. Colours are linear RGB in [0,1]
/// (the photo's sRGB converted to linear), channels in R,G,B order.
struct Particle2D {
  int id = 0;                      ///< 1..P, as drawn in the labels image
  std::vector<cv::Point> contour;  ///< outer contour, pixel coordinates of the photo
  double area = 0;                 ///< pixels
  cv::Rect box;                    ///< axis-aligned bounding box; width/height are the paper's (w,h)
  cv::Vec3f color;                 ///< mean colour, linear RGB
  cv::Mat mask;                    ///< CV_8U, box-sized, 255 inside the particle
  cv::Mat residual;                ///< CV_32FC3, box-sized, linear colour minus mean inside mask, 0 outside
  bool border = false;  ///< cut by the image border: shape and colour kept, left out of the histogram
  int phase = 0;        ///< its kind of particle, 0..K-1 (particlePhases.h); 0 when there is one kind
};

/// The paper's 10-bin area histogram over the non-border particles.
struct AreaHistogram {
  std::array<double, 11>
      edges{};  ///< bin i covers [edges[i], edges[i+1]); the last bin includes its upper edge
  std::array<int, 10> counts{};
  std::array<double, 10> ratios{};  ///< counts / total
  /// Bin of an area, clamped to [0,9].
  int binOf(double area) const;
};

/// A (width, height) box size of the photo's particles and how often it occurs.
struct SizePair {
  int width = 0, height = 0, count = 0;
};

/// Indices of the particles the photo's statistics count: those not cut by its border, or all of
/// them when every particle is (a photo of a few large grains), rather than no statistics at all.
std::vector<std::size_t> statisticalParticles(const std::vector<Particle2D>& particles);

/// Everything later stages need to know about the photo.
struct ExemplarStats {
  std::string name;  ///< the photo's file name
  int imageWidth = 0, imageHeight = 0;
  std::vector<Particle2D> particles;
  cv::Vec3f backgroundColor;   ///< mean background colour, linear RGB
  cv::Mat backgroundMask;      ///< CV_8U, image-sized, 255 on background pixels
  cv::Mat backgroundResidual;  ///< CV_32FC3, image-sized, linear colour minus background mean, 0 on particles
  double areaFraction = 0;     ///< particle pixels / all pixels ("crowdedness")
  double outlineBlur = 0;      ///< pixels: sigma of the Gaussian blur the outlines look blurred by (0: a mask
                               ///< given, or no outline with contrast)
  bool halfMaximumOutlines = false;  ///< outlines drawn half-way up their edges (OutlineMethod)
  double minArea = 0;  ///< pixels; smaller particles were dropped as noise (apply the same to sections)
  int regionsBelowMinArea = 0;       ///< regions (touching ones split) of 4 pixels or more dropped as smaller
  double areaShareBelowMinArea = 0;  ///< their share of the area of all regions of 4 pixels or more
  AreaHistogram histogram;
  std::vector<SizePair> sizePairs;  ///< over non-border particles, sorted by (width, height)
  cv::Mat
      phaseCentres;  ///< K x 4 (K x 3: colour alone) CV_32F, each phase's L*a*b* and grain; empty: one phase
};

}  // namespace solidtex

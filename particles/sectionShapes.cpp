#include "particles/sectionShapes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <opencv2/core.hpp>

#include "segmentation/resampleRegions.h"

namespace solidtex {
namespace {

// The shape's voxels in layer `layer` across `axis`, as pixels. The shapes are randomly turned, so
// an axis-aligned cut is a random section (aligned ones are cut across z, as their xy photo shows them), and
// it is sampled on the voxel grid as the photo's pixels are (an oblique sampling grid would add its own
// jagged edges).
std::vector<cv::Point> layerPixels(const VoxelShape& shape, int axis, int layer) {
  std::vector<cv::Point> pixels;
  const int extent[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  int c[3];
  c[axis] = layer;
  for (c[b] = 0; c[b] < extent[b]; ++c[b])
    for (c[a] = 0; c[a] < extent[a]; ++c[a])
      if (shape.inside[shape.dims.index(c[0], c[1], c[2])]) pixels.emplace_back(c[a], c[b]);
  return pixels;
}

// An axis with the chance of a random plane across it to meet the shape: its extent along the axis
// (a thin disc is seldom cut face on).
int cutAxis(const int (&extent)[3], Rng& rng) {
  auto draw = std::int64_t(uniformIndex(rng, std::uint64_t(extent[0] + extent[1] + extent[2])));
  for (int axis = 0; axis < 2; ++axis)
    if ((draw -= extent[axis]) < 0) return axis;
  return 2;
}

}  // namespace

ShapeColumns photoShapes(const ExemplarStats& stats, double voxelsPerPixel) {
  ShapeColumns out;
  for (std::size_t i : statisticalParticles(stats.particles)) {
    const Particle2D& p = stats.particles[i];
    std::vector<cv::Point> pixels;
    cv::findNonZero(resampleMask(p.mask, voxelsPerPixel), pixels);
    if (double(pixels.size()) >= kMinShapeArea) out.add(measureRegion(pixels));
  }
  return out;
}

// A uniform offset across the shape, as a random plane meets a particle.
ShapeColumns sectionShapes(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                           double sizeFactor, int shapes, int planesPerShape, SectionAxis cuts, Rng& rng) {
  const std::vector<std::size_t> sources = statisticalParticles(stats.particles);
  const auto scaled = [&](int pixels) {
    return std::max(1, int(std::lround(pixels * voxelsPerPixel * sizeFactor)));
  };
  ShapeColumns out;
  for (int s = 0; s < shapes && !sources.empty(); ++s) {
    const Particle2D& source = stats.particles[sources[uniformIndex(rng, sources.size())]];
    const ParticleSize size = factory.pickDepth(source.box.width, source.box.height, rng, source.phase);
    const VoxelShape shape = factory.make(scaled(size.width), scaled(size.height), scaled(size.depth), rng,
                                          factory.phaseOf(size.source));
    const int extent[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
    for (int p = 0; p < planesPerShape; ++p) {
      const int axis = factory.aligned()               ? 2  // as the xy photo shows them
                       : cuts == SectionAxis::ByExtent ? cutAxis(extent, rng)
                                                       : int(uniformIndex(rng, 3));
      const std::vector<cv::Point> pixels =
          layerPixels(shape, axis, int(uniformIndex(rng, std::uint64_t(extent[axis]))));
      if (double(pixels.size()) >= kMinShapeArea) out.add(measureRegion(pixels));
    }
  }
  return out;
}

}  // namespace solidtex

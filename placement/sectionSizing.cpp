#include "placement/sectionSizing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/distributionDistance.h"
#include "common/randomDirection.h"

namespace solidtex {
namespace {

constexpr std::uint64_t kSectionStream = 0x6b65726e;  // "kern"
constexpr double kSampleSide = 64;  // voxels of the largest particle box the sections are measured on
constexpr double kSmallestFactor = 1, kLargestFactor = 2, kFactorStep = 0.02;
// Light: on sphere kernels with a few hundred photo particles, counting noise, not the smoothing's
// bias, limits the unfolding (stronger smoothing flattens a two-sized truth into one broad hump).
constexpr double kSmoothing = 0.05;
// Factors whose predicted sections are this close (KS) to the best one's fit as well, given the
// photo's own counting noise (a KS of about 0.87 / sqrt(n) between two photos of n particles).
constexpr double kKsTolerance = 0.01, kKsNoiseShare = 0.25;
// Of a class's sections, at or above the photo's smallest area. A mix of sizes 10:1 in volume holds
// many particles whose sections the photo shows one time in three or four; leaving their class out
// gives their few sections to larger classes and the 3D sizes too few small particles.
constexpr double kMinVisibleShare = 0.2;
constexpr std::uint64_t kBootstrapStream = 0x626f6f74;  // "boot"
constexpr int kBandPoints = 32;  // volumes the band of the implied volume CDF is given at

std::vector<Eigen::Vector3d> centresOf(const VoxelShape& shape) {
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < shape.dims.z; ++k)
    for (int j = 0; j < shape.dims.y; ++j)
      for (int i = 0; i < shape.dims.x; ++i)
        if (shape.inside[shape.dims.index(i, j, k)]) out.emplace_back(i, j, k);
  return out;
}

// A random plane cutting the shape: its section area is the count of voxel centres within half a
// voxel of it (a unit-thick slab holds area x 1 of volume), and the shape's extent along the normal
// is how likely a plane of a random family is to cut it at all. Aligned particles are cut across z,
// as the xy photo shows them.
SectionSample cutAtRandom(const std::vector<Eigen::Vector3d>& centres, std::vector<double>& along,
                          bool acrossZ, Rng& rng) {
  const Eigen::Vector3d n = acrossZ ? Eigen::Vector3d::UnitZ() : randomDirection(rng);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    along[i] = n.dot(centres[i]);
    lo = std::min(lo, along[i]);
    hi = std::max(hi, along[i]);
  }
  const double width = hi - lo + 1;
  const double at = lo - 0.5 + uniform01(rng) * width;
  const auto inSlab =
      std::count_if(along.begin(), along.end(), [&](double t) { return std::abs(t - at) < 0.5; });
  return {0, double(inSlab), width};
}

std::vector<SectionSample> sampleClass(const ExemplarStats& stats, const ParticleFactory& factory,
                                       const std::vector<std::size_t>& members, double scale, Rng& rng,
                                       int shapes, int planes) {
  const auto scaled = [&](int pixels) { return std::max(1, int(std::lround(pixels * scale))); };
  std::vector<SectionSample> out;
  std::vector<double> along;
  for (int s = 0; s < shapes; ++s) {
    const Particle2D& member = stats.particles[members[uniformIndex(rng, members.size())]];
    const ParticleSize size = factory.pickDepth(member.box.width, member.box.height, rng, member.phase);
    const std::vector<Eigen::Vector3d> centres = centresOf(factory.make(
        scaled(size.width), scaled(size.height), scaled(size.depth), rng, factory.phaseOf(size.source)));
    along.resize(centres.size());
    for (int p = 0; p < planes; ++p) {
      SectionSample sample = cutAtRandom(centres, along, factory.aligned(), rng);
      sample.area /= scale * scale;
      sample.width /= scale;
      sample.volume = double(centres.size()) / (scale * scale * scale);
      out.push_back(sample);
    }
  }
  return out;
}

// Sections of one particle of class j at `factor`: area, and weight (chance to be cut) per shape.
template <class Visit>
void forEachSection(const std::vector<SectionSample>& samples, const std::vector<int>& samplesPerClass,
                    double minArea, double factor, Visit visit) {
  for (const SectionSample& s : samples) {
    const double area = s.area * factor * factor;
    if (s.area > 0 && area >= minArea)
      visit(s.particleClass, area, s.width * factor / samplesPerClass[std::size_t(s.particleClass)]);
  }
}

std::vector<int> samplesPerClass(const std::vector<SectionSample>& samples, int classes) {
  std::vector<int> count(std::size_t(classes), 0);
  for (const SectionSample& s : samples) ++count[std::size_t(s.particleClass)];
  return count;
}

// KS between the photo's areas and the sections predicted for 3D class shares x at `factor`. The
// samples come sorted by area, so the predicted sections do too: a factor scales every area alike.
double predictedKs(const std::vector<SectionSample>& samples, const std::vector<int>& perClass,
                   double minArea, double factor, const Eigen::VectorXd& x,
                   const std::vector<std::pair<double, double>>& photo) {
  std::vector<std::pair<double, double>> predicted;  // (area, weight)
  forEachSection(samples, perClass, minArea, factor, [&](int c, double area, double weight) {
    if (x[c] > 0) predicted.emplace_back(area, x[c] * weight);
  });
  if (predicted.empty() || photo.empty()) return 1;
  double total = 0, photoTotal = 0;
  for (const auto& p : predicted) total += p.second;
  for (const auto& p : photo) photoTotal += p.second;
  // Both CDFs just below each photo area, then at it (ties of equal areas counted together).
  double ks = 0, cumulative = 0, photoCumulative = 0;
  std::size_t next = 0;
  for (const auto& [area, weight] : photo) {
    while (next < predicted.size() && predicted[next].first < area) cumulative += predicted[next++].second;
    ks = std::max(ks, std::abs(cumulative / total - photoCumulative / photoTotal));
    while (next < predicted.size() && predicted[next].first <= area) cumulative += predicted[next++].second;
    photoCumulative += weight;
    ks = std::max(ks, std::abs(cumulative / total - photoCumulative / photoTotal));
  }
  return ks;
}

// Miles and Lantuejoul: a particle of box w x h lies wholly inside a W x H photo for only
// (W - w)(H - h) of its positions, so the photo's border drops large particles more often than small
// ones; weighting each inner particle by the inverse restores the sections' true proportions.
double borderCorrection(const ExemplarStats& stats, const Particle2D& p) {
  const double free = double(stats.imageWidth - p.box.width) * double(stats.imageHeight - p.box.height);
  return free > 0 && stats.imageWidth > 0 ? double(stats.imageWidth) * stats.imageHeight / free : 1.0;
}

}  // namespace

Sizing parseSizing(const std::string& name) {
  if (name == "bbox") return Sizing::Bbox;
  if (name == "sections") return Sizing::Sections;
  throw OptionError("unknown sizing '" + name + "': use bbox or sections");
}

const char* sizingName(Sizing sizing) { return sizing == Sizing::Bbox ? "bbox" : "sections"; }

int AreaClasses::classOfArea(double area) const {
  if (area < edges.front()) return -1;
  const auto upper = std::upper_bound(edges.begin(), edges.end(), area);
  return std::min(int(upper - edges.begin()) - 1, count() - 1);
}

AreaClasses areaClassesOf(const ExemplarStats& stats, int classes) {
  std::vector<std::size_t> counted = statisticalParticles(stats.particles);
  std::erase_if(counted, [&](std::size_t i) {
    return stats.particles[i].box.width <= 0 || stats.particles[i].box.height <= 0;
  });
  if (counted.empty()) throw InputError("section sizing: the photo has no particle to take sizes from");
  double lo = INFINITY, hi = 0;
  for (std::size_t i : counted) {
    lo = std::min(lo, stats.particles[i].area);
    hi = std::max(hi, stats.particles[i].area);
  }
  // A little room below the smallest particle: larger particles' sections that land there are ones
  // the photo would have shown but does not, and the unfolding must see them to avoid them.
  lo = std::max({stats.minArea, lo / 2, 1e-9});
  hi = std::max(hi, lo * 1.0001);
  AreaClasses out;
  for (int c = 0; c <= classes; ++c) out.edges.push_back(lo * std::pow(hi / lo, double(c) / classes));
  out.classOf.assign(stats.particles.size(), -1);
  for (std::size_t i : counted) out.classOf[i] = std::max(0, out.classOfArea(stats.particles[i].area));
  return out;
}

std::vector<SectionSample> sampleParticleSections(const ExemplarStats& stats, const ParticleFactory& factory,
                                                  const AreaClasses& classes, double voxelsPerPixel,
                                                  std::uint64_t seed, int shapesPerClass,
                                                  int planesPerShape) {
  std::vector<std::vector<std::size_t>> members(std::size_t(classes.count()));
  int largestSide = 1;
  for (std::size_t i = 0; i < stats.particles.size(); ++i)
    if (classes.classOf[i] >= 0) {
      members[std::size_t(classes.classOf[i])].push_back(i);
      largestSide = std::max({largestSide, stats.particles[i].box.width, stats.particles[i].box.height});
    }
  const double scale = std::min(voxelsPerPixel, kSampleSide / largestSide);
  std::vector<std::vector<SectionSample>> perClass(members.size());
  tbb::parallel_for(std::size_t(0), members.size(), [&](std::size_t c) {
    if (members[c].empty()) return;
    Rng rng(deriveSeed(seed, kSectionStream + c));
    perClass[c] = sampleClass(stats, factory, members[c], scale, rng, shapesPerClass, planesPerShape);
    for (SectionSample& s : perClass[c]) s.particleClass = int(c);
  });
  std::vector<SectionSample> out;
  for (const auto& samples : perClass) out.insert(out.end(), samples.begin(), samples.end());
  return out;
}

Eigen::MatrixXd sectionKernel(const std::vector<SectionSample>& samples, const AreaClasses& classes,
                              double minArea, double sizeFactor) {
  const std::vector<int> perClass = samplesPerClass(samples, classes.count());
  Eigen::MatrixXd kernel = Eigen::MatrixXd::Zero(classes.count(), classes.count());
  forEachSection(samples, perClass, minArea, sizeFactor, [&](int c, double area, double weight) {
    kernel(std::max(0, classes.classOfArea(area)), c) += weight;
  });
  // A class whose sections nearly all fall below the photo's specks is all but invisible in it: the
  // photo cannot say how many there are, and an unfolding would keep whatever it started with.
  Eigen::VectorXd cut = Eigen::VectorXd::Zero(classes.count());
  forEachSection(samples, perClass, 0, sizeFactor, [&](int c, double, double weight) { cut[c] += weight; });
  for (int c = 0; c < classes.count(); ++c)
    if (kernel.col(c).sum() < kMinVisibleShare * cut[c]) kernel.col(c).setZero();
  return kernel;
}

Eigen::VectorXd unfoldSections(const Eigen::MatrixXd& kernel, const Eigen::VectorXd& observed,
                               int iterations) {
  const Eigen::Index n = kernel.cols();
  const Eigen::VectorXd efficiency = kernel.colwise().sum().transpose();
  const Eigen::ArrayXd made = (efficiency.array() > 0).cast<double>();
  Eigen::VectorXd x = made.matrix();
  if (x.sum() == 0) return x;
  x /= x.sum();
  for (int it = 0; it < iterations; ++it) {
    const Eigen::VectorXd predicted = kernel * x;
    Eigen::VectorXd ratio = Eigen::VectorXd::Zero(observed.size());
    for (Eigen::Index i = 0; i < observed.size(); ++i)
      if (predicted[i] > 0) ratio[i] = observed[i] / predicted[i];
    const Eigen::VectorXd back = kernel.transpose() * ratio;
    for (Eigen::Index j = 0; j < n; ++j) x[j] = made[j] > 0 ? x[j] * back[j] / efficiency[j] : 0;
    // The S of EMS: each class passes kSmoothing of its share to each neighbour (the ends keep theirs).
    Eigen::VectorXd smooth = x;
    for (Eigen::Index j = 0; j < n; ++j)
      smooth[j] = (1 - 2 * kSmoothing) * x[j] +
                  kSmoothing * ((j > 0 ? x[j - 1] : x[j]) + (j + 1 < n ? x[j + 1] : x[j]));
    x = (smooth.array() * made).matrix();
    const double total = x.sum();
    if (!(total > 0)) break;
    x /= total;
  }
  return x;
}

namespace {

// The photo's counted particles per class and their (area, weight) sorted by area, each weighted
// for the border that drops large ones more often.
struct PhotoSections {
  Eigen::VectorXd perClass;
  std::vector<std::pair<double, double>> areas;
};

PhotoSections photoSectionsOf(const ExemplarStats& stats, const AreaClasses& classes) {
  PhotoSections out{Eigen::VectorXd::Zero(classes.count()), {}};
  for (std::size_t i = 0; i < stats.particles.size(); ++i)
    if (classes.classOf[i] >= 0) {
      const double weight = borderCorrection(stats, stats.particles[i]);
      out.perClass[classes.classOf[i]] += weight;
      out.areas.emplace_back(stats.particles[i].area, weight);
    }
  std::sort(out.areas.begin(), out.areas.end());
  return out;
}

struct Fit {
  double factor = 1, ks = 1;
  Eigen::VectorXd shares;
};

// Section kernels at factors 1 to 2, in steps of kFactorStep: the same for every resample of the photo.
std::vector<Eigen::MatrixXd> kernelsPerFactor(const std::vector<SectionSample>& samples,
                                              const AreaClasses& classes, double minArea) {
  std::vector<Eigen::MatrixXd> kernels;
  for (int step = 0; kSmallestFactor + step * kFactorStep <= kLargestFactor + 1e-9; ++step)
    kernels.push_back(sectionKernel(samples, classes, minArea, kSmallestFactor + step * kFactorStep));
  return kernels;
}

// Larger particles with their shares shifted to smaller classes give much the same sections, so
// many factors fit about as well: the fits whose predicted sections are within the photo's
// counting noise of the best one's, smallest factor first.
std::vector<Fit> goodFits(const std::vector<SectionSample>& samples,
                          const std::vector<Eigen::MatrixXd>& kernels, const AreaClasses& classes,
                          double minArea, const PhotoSections& photo) {
  const std::vector<int> perClass = samplesPerClass(samples, classes.count());
  const Eigen::VectorXd observed = photo.perClass / photo.perClass.sum();
  std::vector<Fit> fits;
  for (std::size_t step = 0; step < kernels.size(); ++step) {
    const double factor = kSmallestFactor + double(step) * kFactorStep;
    const Eigen::VectorXd x = unfoldSections(kernels[step], observed);
    fits.push_back({factor, predictedKs(samples, perClass, minArea, factor, x, photo.areas), x});
  }
  double best = 1;
  for (const Fit& fit : fits) best = std::min(best, fit.ks);
  const double tolerance = std::max(kKsTolerance, kKsNoiseShare / std::sqrt(double(photo.areas.size())));
  std::erase_if(fits, [&](const Fit& fit) { return !(fit.ks <= best + tolerance); });
  if (fits.empty()) fits.push_back({1, 1, observed});  // no KS was a number
  return fits;
}

// The smallest good factor keeps the largest classes for the largest particles instead of
// inflating them beyond any the photo implies.
Fit smallestGoodFit(const std::vector<Fit>& good, const PhotoSections& photo) {
  if (!(good.front().shares.sum() > 0))  // no shape was cut above the photo's specks
    return {1, 1, photo.perClass / photo.perClass.sum()};
  return good.front();
}

// The photo's counted particles drawn again with replacement, as another photo of as many might show.
PhotoSections resampled(const PhotoSections& photo, const AreaClasses& classes, Rng& rng) {
  PhotoSections out{Eigen::VectorXd::Zero(classes.count()), {}};
  for (std::size_t n = 0; n < photo.areas.size(); ++n) {
    const auto& [area, weight] = photo.areas[uniformIndex(rng, photo.areas.size())];
    out.perClass[std::max(0, classes.classOfArea(area))] += weight;
    out.areas.emplace_back(area, weight);
  }
  std::sort(out.areas.begin(), out.areas.end());
  return out;
}

// Mean particle volume a fit implies, up to a constant: each class's middle area, scaled by the
// factor, to the power 3/2.
double impliedMeanVolume(const Fit& fit, const AreaClasses& classes) {
  double volume = 0, total = 0;
  for (int c = 0; c < classes.count(); ++c) {
    const double area = std::sqrt(classes.edges[std::size_t(c)] * classes.edges[std::size_t(c) + 1]) *
                        fit.factor * fit.factor;
    volume += fit.shares[c] * std::pow(area, 1.5);
    total += fit.shares[c];
  }
  return total > 0 ? volume / total : 0;
}

// The 3D volume CDF a fit implies at `at`: each class's share over the volumes of the shapes made
// for it (every sample is one plane through one shape, so each shape counts alike), scaled by the
// factor cubed.
std::vector<double> impliedVolumeCdf(const std::vector<SectionSample>& samples,
                                     const std::vector<int>& perClass, const Fit& fit,
                                     const std::vector<double>& at) {
  const double cube = fit.factor * fit.factor * fit.factor;
  std::vector<double> cdf(at.size(), 0.0);
  const double total = fit.shares.sum();
  if (!(total > 0)) return cdf;
  for (const SectionSample& s : samples) {
    const double share = fit.shares[s.particleClass] / total / perClass[std::size_t(s.particleClass)];
    if (share <= 0) continue;
    for (std::size_t i = std::size_t(std::lower_bound(at.begin(), at.end(), s.volume * cube) - at.begin());
         i < at.size(); ++i)
      cdf[i] += share;
  }
  for (double& f : cdf) f = std::min(f, 1.0);  // the shares' sum may pass 1 by rounding
  return cdf;
}

// Log-spaced volumes from half the smallest shape's to twice the largest's, at the factors 1 and 2
// that bound every fit.
std::vector<double> bandVolumesOf(const std::vector<SectionSample>& samples) {
  double lo = INFINITY, hi = 0;
  for (const SectionSample& s : samples)
    if (s.volume > 0) lo = std::min(lo, s.volume), hi = std::max(hi, s.volume);
  if (!(hi > 0)) return {};
  lo *= 0.5 * std::pow(kSmallestFactor, 3);
  hi *= 2 * std::pow(kLargestFactor, 3);
  std::vector<double> volumes;
  for (int i = 0; i < kBandPoints; ++i)
    volumes.push_back(lo * std::pow(hi / lo, double(i) / (kBandPoints - 1)));
  return volumes;
}

// How far the 3D sizes could move with another photo of as many particles: the fit redone on
// bootstrap resamples of the photo's particles (the particle shapes' sections kept).
SizingUncertainty bootstrap(const std::vector<SectionSample>& samples,
                            const std::vector<Eigen::MatrixXd>& kernels, const AreaClasses& classes,
                            double minArea, const PhotoSections& photo, const Fit& fit, int bootstraps,
                            std::uint64_t seed) {
  const auto count = static_cast<std::size_t>(bootstraps);
  const std::vector<int> perClass = samplesPerClass(samples, classes.count());
  SizingUncertainty u;
  u.bandVolumes = bandVolumesOf(samples);
  std::vector<double> factors(count), volumes(count);
  std::vector<std::vector<double>> cdfs(count);
  tbb::parallel_for(0, bootstraps, [&](int b) {
    Rng rng(deriveSeed(seed, kBootstrapStream + std::uint64_t(b)));
    const PhotoSections again = resampled(photo, classes, rng);
    const std::vector<Fit> fits = goodFits(samples, kernels, classes, minArea, again);
    const Fit smallest = smallestGoodFit(fits, again);
    factors[std::size_t(b)] = smallest.factor;
    volumes[std::size_t(b)] = impliedMeanVolume(smallest, classes);
    // Any good factor is as likely as another: the band holds what the sections cannot decide too.
    cdfs[std::size_t(b)] =
        impliedVolumeCdf(samples, perClass, fits[uniformIndex(rng, fits.size())], u.bandVolumes);
  });
  u.bandCdf = impliedVolumeCdf(samples, perClass, fit, u.bandVolumes);
  const PercentileBand band = percentileBand(cdfs, 0.05, 0.95);
  u.bandLow = band.low;
  u.bandHigh = band.high;
  const double reference = impliedMeanVolume(fit, classes);
  double squares = 0;
  for (double v : volumes) squares += (v - reference) * (v - reference);
  std::sort(factors.begin(), factors.end());
  u.bootstraps = bootstraps;
  u.sizeFactorLow = factors[std::size_t(0.05 * (bootstraps - 1))];
  u.sizeFactorHigh = factors[std::size_t(std::ceil(0.95 * (bootstraps - 1)))];
  u.meanVolumeSpread = reference > 0 ? std::sqrt(squares / bootstraps) / reference : 0;
  return u;
}

}  // namespace

SectionSizing fitSectionSizing(const ExemplarStats& stats, const ParticleFactory& factory,
                               double voxelsPerPixel, std::uint64_t seed, int bootstraps) {
  const AreaClasses classes = areaClassesOf(stats);
  const PhotoSections photo = photoSectionsOf(stats, classes);
  std::vector<SectionSample> samples = sampleParticleSections(stats, factory, classes, voxelsPerPixel, seed);
  std::stable_sort(samples.begin(), samples.end(),
                   [](const SectionSample& a, const SectionSample& b) { return a.area < b.area; });
  const std::vector<Eigen::MatrixXd> kernels = kernelsPerFactor(samples, classes, stats.minArea);
  const Fit fit = smallestGoodFit(goodFits(samples, kernels, classes, stats.minArea, photo), photo);
  SectionSizing sizing;
  if (bootstraps > 0)
    sizing.uncertainty = bootstrap(samples, kernels, classes, stats.minArea, photo, fit, bootstraps, seed);
  sizing.sizeFactor = fit.factor;
  sizing.predictedKs = fit.ks;
  // A class's share goes to its photo particles as the border correction weighs them, so within a
  // class the photo's sizes recur in their true proportions.
  sizing.particleWeights.assign(stats.particles.size(), 0);
  for (std::size_t i = 0; i < stats.particles.size(); ++i)
    if (const int c = classes.classOf[i]; c >= 0) {
      sizing.particleWeights[i] =
          fit.shares[c] * borderCorrection(stats, stats.particles[i]) / photo.perClass[c];
      sizing.binRatios[std::size_t(stats.histogram.binOf(stats.particles[i].area))] +=
          sizing.particleWeights[i];
    }
  return sizing;
}

}  // namespace solidtex

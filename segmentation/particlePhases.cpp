#include "segmentation/particlePhases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "common/Error.h"
#include "io/imageIO.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/summarize.h"
#include "segmentation/particleShading.h"

namespace solidtex {
namespace {

constexpr int kAttempts = 3;

// A grain contrast weighs this many L*a*b* units a unit: it is read about five times as finely as a
// colour (plain particles' grain reads within about one L* unit on the truths, where shading
// spreads a phase's colours over about five), so a phase told apart by its grain alone is as far
// from the next as one told apart by colour.
constexpr float kGrainWeight = 5;

// The particles' features, one row each: mean colour in L*a*b* and grain contrast times
// kGrainWeight. A particle too small to read its grain takes the median of those that show one;
// when none shows one, the colours alone.
cv::Mat particleFeatures(const ExemplarStats& stats) {
  std::vector<cv::Vec3f> linear;
  std::vector<double> grain, measured;
  for (const Particle2D& p : stats.particles) {
    linear.push_back(p.color);
    grain.push_back(grainContrast(p));
    if (!std::isnan(grain.back())) measured.push_back(grain.back());
  }
  // No particle large enough to show a grain: a constant column would only add parameters to the BIC.
  if (measured.empty()) return labOfColours(linear);
  std::nth_element(measured.begin(), measured.begin() + std::ptrdiff_t(measured.size() / 2), measured.end());
  const double median = measured[measured.size() / 2];
  cv::Mat features;
  cv::Mat grainColumn(int(grain.size()), 1, CV_32F);
  for (std::size_t i = 0; i < grain.size(); ++i)
    grainColumn.at<float>(int(i)) = kGrainWeight * float(std::isnan(grain[i]) ? median : grain[i]);
  cv::hconcat(labOfColours(linear), grainColumn, features);
  return features;
}

// Centres in the features' weighting, from the reports' L* units (the centres ParticlePhases
// holds), and back.
cv::Mat centresWithWeightedGrain(const cv::Mat& centres) {
  cv::Mat out = centres.clone();
  if (out.cols > 3) out.col(3) *= kGrainWeight;
  return out;
}

cv::Mat centresWithGrainInLightness(const cv::Mat& centres) {
  cv::Mat out = centres.clone();
  if (out.cols > 3) out.col(3) /= kGrainWeight;
  return out;
}

// The nearest centre over the features both hold (centres of three columns, from a solid made
// before phases read grain, are colours alone).
int nearestRow(const float* features, const cv::Mat& centres) {
  int best = 0;
  float bestDistance = std::numeric_limits<float>::max();
  for (int c = 0; c < centres.rows; ++c) {
    const float* m = centres.ptr<float>(c);
    float d = 0;
    for (int j = 0; j < centres.cols; ++j) d += (features[j] - m[j]) * (features[j] - m[j]);
    if (d < bestDistance) best = c, bestDistance = d;
  }
  return best;
}

// Centres reordered darkest first, and each sample's phase its cluster's new rank.
ParticlePhases sortedPhases(const cv::Mat& centres, const std::vector<int>& labels, std::string method) {
  std::vector<int> order(std::size_t(centres.rows)), rank(std::size_t(centres.rows));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return centres.at<float>(a, 0) < centres.at<float>(b, 0); });
  ParticlePhases out;
  out.method = std::move(method);
  out.centres.create(centres.rows, centres.cols, CV_32F);
  for (int r = 0; r < centres.rows; ++r) {
    centres.row(order[std::size_t(r)]).copyTo(out.centres.row(r));
    rank[std::size_t(order[std::size_t(r)])] = r;
  }
  out.phaseOf.reserve(labels.size());
  for (int label : labels) out.phaseOf.push_back(rank[std::size_t(label)]);
  out.centres = centresWithGrainInLightness(out.centres);
  return out;
}

struct Clustering {
  cv::Mat centres;
  std::vector<int> labels;
  double bic = 0;
};

// A covariance floor (squared L*a*b* units): colours a drawn image repeats exactly, or a phase of one
// particle, would otherwise have an infinite density.
constexpr double kCovarianceFloor = 25.0;

// The BIC of the Gaussian mixture the clustering stands for: each cluster's mean and covariance
// (plus the floor), full or spherical, the weights its share. Full covariances follow the line
// shading draws a phase's colours along, where one pooled spherical variance (X-means) splits it
// into ever more phases; a few particles a phase (smarties) have too few colours for a full
// covariance's parameters, and spherical ones tell them apart.
double bicOf(const cv::Mat& samples, const std::vector<int>& labels, int k, bool fullCovariance) {
  const int n = samples.rows, d = samples.cols;
  cv::Mat x;
  samples.convertTo(x, CV_64F);
  struct Component {
    double logWeight = 0;
    cv::Mat mean, inverse;
    double logNormalizer = 0;
  };
  std::vector<Component> components;
  for (int c = 0; c < k; ++c) {
    cv::Mat members;
    for (int i = 0; i < n; ++i)
      if (labels[std::size_t(i)] == c) members.push_back(x.row(i));
    if (members.empty()) continue;
    cv::Mat scatter, mean;
    cv::calcCovarMatrix(members, scatter, mean, cv::COVAR_NORMAL | cv::COVAR_ROWS | cv::COVAR_SCALE, CV_64F);
    if (!fullCovariance) scatter = cv::Mat::eye(d, d, CV_64F) * (cv::trace(scatter)[0] / d);
    const cv::Mat covariance = scatter + cv::Mat::eye(d, d, CV_64F) * kCovarianceFloor;
    components.push_back({std::log(double(members.rows) / n), mean, covariance.inv(cv::DECOMP_CHOLESKY),
                          -0.5 * (d * std::log(2 * M_PI) + std::log(cv::determinant(covariance)))});
  }
  double logLikelihood = 0;
  std::vector<double> terms(components.size());
  for (int i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < components.size(); ++c) {
      const cv::Mat difference = x.row(i) - components[c].mean;
      terms[c] = components[c].logWeight + components[c].logNormalizer -
                 0.5 * difference.dot(difference * components[c].inverse);
    }
    const double top = *std::max_element(terms.begin(), terms.end());
    double sum = 0;
    for (double t : terms) sum += std::exp(t - top);
    logLikelihood += top + std::log(sum);
  }
  const double parameters = (k - 1) + k * (d + (fullCovariance ? d * (d + 1) / 2 : 1));
  return -2 * logLikelihood + parameters * std::log(double(n));
}

Clustering cluster(const cv::Mat& samples, int k, std::uint64_t seed) {
  Clustering out;
  cv::Mat labels;
  if (k == 1) {
    cv::reduce(samples, out.centres, 0, cv::REDUCE_AVG);
    labels = cv::Mat::zeros(samples.rows, 1, CV_32S);
  } else {
    cv::theRNG().state = seed == 0 ? 1 : seed;  // k-means++ draws from OpenCV's thread's generator
    cv::kmeans(samples, k, labels,
               cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4), kAttempts,
               cv::KMEANS_PP_CENTERS, out.centres);
  }
  out.labels.assign(labels.begin<int>(), labels.end<int>());
  out.bic = std::min(bicOf(samples, out.labels, k, true), bicOf(samples, out.labels, k, false));
  return out;
}

// The fewest particles a phase the count chooses may hold: at least two and 1 % of the photo's. A
// phase of one odd particle (two touching particles of different colours read as one) has one
// section for its sizes and only the covariance floor for its model, which the BIC cannot weigh.
bool everyClusterHoldsEnough(const Clustering& c, int k) {
  const int n = int(c.labels.size());
  const int least = std::max(2, int(std::ceil(0.01 * n)));
  std::vector<int> counts(std::size_t(k), 0);
  for (int label : c.labels) ++counts[std::size_t(label)];
  return *std::min_element(counts.begin(), counts.end()) >= least;
}

std::string nameOf(const ExemplarStats& stats) { return stats.name.empty() ? "the photo" : stats.name; }

}  // namespace

ParticlePhases classifyParticles(const ExemplarStats& stats, int phases, std::uint64_t seed) {
  if (phases < 0 || phases > kMaxPhases)
    throw OptionError("--phases must be auto or in [1, " + std::to_string(kMaxPhases) + "], got " +
                      std::to_string(phases));
  const int n = int(stats.particles.size());
  if (n < phases)
    throw InputError(nameOf(stats) + " shows " + std::to_string(n) + " particles, fewer than --phases " +
                     std::to_string(phases));
  const cv::Mat samples = particleFeatures(stats);
  if (phases > 0) {
    const Clustering c = cluster(samples, phases, seed);
    return sortedPhases(c.centres, c.labels, "k-means of the particles' colours in CIE L*a*b* and grain");
  }
  std::vector<double> bic;
  Clustering best;
  for (int k = 1; k <= std::min(kMaxPhases, n); ++k) {
    Clustering c = cluster(samples, k, seed);
    bic.push_back(c.bic);
    if (k == 1 || (c.bic < best.bic && everyClusterHoldsEnough(c, k))) best = std::move(c);
  }
  ParticlePhases out =
      sortedPhases(best.centres, best.labels,
                   "k-means of the particles' colours in CIE L*a*b* and grain, the count by BIC");
  out.bic = std::move(bic);
  return out;
}

ParticlePhases particlePhasesOfLabels(const ExemplarStats& stats, const cv::Mat& labelImage,
                                      const std::string& name, int maxPhases) {
  if (labelImage.type() != CV_32FC3) throw InputError(name + ": a phase mask must be a colour image");
  if (labelImage.cols != stats.imageWidth || labelImage.rows != stats.imageHeight)
    throw InputError(name + " is " + std::to_string(labelImage.cols) + "x" + std::to_string(labelImage.rows) +
                     " but the photo is " + std::to_string(stats.imageWidth) + "x" +
                     std::to_string(stats.imageHeight));
  cv::Mat bytes;
  labelImage.convertTo(bytes, CV_8UC3, 255.0);
  const auto packedAt = [&](int x, int y) {
    const cv::Vec3b v = bytes.at<cv::Vec3b>(y, x);
    return (std::uint32_t(v[0]) << 16) | (std::uint32_t(v[1]) << 8) | v[2];
  };
  std::vector<std::uint32_t> majority(stats.particles.size());
  for (std::size_t i = 0; i < stats.particles.size(); ++i) {
    const Particle2D& p = stats.particles[i];
    std::map<std::uint32_t, int> votes;
    for (int y = 0; y < p.box.height; ++y)
      for (int x = 0; x < p.box.width; ++x)
        if (p.mask.at<std::uint8_t>(y, x)) ++votes[packedAt(p.box.x + x, p.box.y + y)];
    majority[i] = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
                    return a.second < b.second;
                  })->first;
  }
  std::vector<std::uint32_t> values = majority;
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (int(values.size()) > maxPhases)
    throw InputError(name + " gives the particles " + std::to_string(values.size()) + " phases, more than " +
                     (maxPhases == kMaxPhases ? std::string("8") : "--phases " + std::to_string(maxPhases)));
  const cv::Mat samples = particleFeatures(stats);
  ParticlePhases out;
  out.method = "phase mask " + name;
  out.centres = cv::Mat::zeros(int(values.size()), samples.cols, CV_32F);
  std::vector<int> counts(values.size(), 0);
  out.phaseOf.resize(majority.size());
  for (std::size_t i = 0; i < majority.size(); ++i) {
    const int c = int(std::lower_bound(values.begin(), values.end(), majority[i]) - values.begin());
    out.phaseOf[i] = c;
    out.centres.row(c) += samples.row(int(i));
    ++counts[std::size_t(c)];
  }
  for (int c = 0; c < out.centres.rows; ++c) out.centres.row(c) /= double(counts[std::size_t(c)]);
  out.centres = centresWithGrainInLightness(out.centres);
  return out;
}

ParticlePhases nearestPhases(const ExemplarStats& stats, const cv::Mat& centres) {
  const cv::Mat samples = particleFeatures(stats);
  ParticlePhases out;
  out.method = "the nearest of the solid's phase centres (colour and grain)";
  out.centres = centres.clone();
  out.phaseOf.resize(stats.particles.size());
  const cv::Mat weighted = centresWithWeightedGrain(centres);
  for (int i = 0; i < samples.rows; ++i)
    out.phaseOf[std::size_t(i)] = nearestRow(samples.ptr<float>(i), weighted);
  return out;
}

std::optional<ParticlePhases> findPhases(const ExemplarStats& stats, const PhaseOptions& options,
                                         std::uint64_t seed) {
  if (options.phases < 0 || options.phases > kMaxPhases)
    throw OptionError("--phases must be auto or in [1, 8], got " + std::to_string(options.phases));
  if (options.maskPath)
    return particlePhasesOfLabels(stats, loadPhoto(*options.maskPath), *options.maskPath,
                                  options.phases >= 2 ? options.phases : kMaxPhases);
  if (options.phases == 1) return std::nullopt;
  return classifyParticles(stats, options.phases, seed);
}

cv::Mat labOfColours(const std::vector<cv::Vec3f>& linear) {
  cv::Mat colours(int(linear.size()), 1, CV_32FC3);
  for (std::size_t i = 0; i < linear.size(); ++i) colours.at<cv::Vec3f>(int(i)) = linear[i];
  return segmentation::detail::linearToLab(colours).reshape(1, colours.rows).clone();
}

void assignPhases(ExemplarStats& stats, const ParticlePhases& phases) {
  if (phases.phaseOf.size() != stats.particles.size())
    throw std::invalid_argument("assignPhases: one phase per particle");
  for (std::size_t i = 0; i < stats.particles.size(); ++i) stats.particles[i].phase = phases.phaseOf[i];
  stats.phaseCentres = phases.centres.clone();
}

std::vector<double> phaseAreaFractions(const ExemplarStats& stats) {
  std::vector<double> areas(std::size_t(std::max(1, stats.phaseCentres.rows)), 0.0);
  double total = 0;
  for (const Particle2D& p : stats.particles) {
    areas[std::size_t(p.phase)] += p.area;
    total += p.area;
  }
  // The particles' areas split the photo's particle fraction, which counts their outlines alike.
  for (double& area : areas) area = total > 0 ? stats.areaFraction * area / total : 0;
  return areas;
}

ExemplarStats phaseStats(const ExemplarStats& stats, int phase) {
  ExemplarStats out = stats;
  out.particles.clear();
  for (const Particle2D& p : stats.particles)
    if (p.phase == phase) out.particles.push_back(p);
  out.areaFraction = phaseAreaFractions(stats)[std::size_t(phase)];
  std::vector<const Particle2D*> counted;
  for (std::size_t i : statisticalParticles(out.particles)) counted.push_back(&out.particles[i]);
  out.histogram = segmentation::detail::buildAreaHistogram(counted);
  out.sizePairs = segmentation::detail::buildSizePairs(counted);
  return out;
}

}  // namespace solidtex

#include "synthesis/detail/discreteSolve.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "synthesis/detail/VoxelBatches.h"

namespace solidtex::synthesis::detail {

std::vector<std::int64_t> positionHistogramOf(const std::vector<std::int32_t>& source, int pixels) {
  std::vector<std::int64_t> h(pixels, 0);
  for (std::int32_t p : source)
    if (p >= 0) ++h[p];
  return h;
}

namespace {

struct Proposal {
  std::int32_t pixel;
  float weight;
};

/// Per-thread working memory of one voxel's choice.
struct VoxelScratch {
  std::vector<Proposal> proposals;
  std::vector<float> votes, colors;
};

/// Eq. 3's factor 1 / (1 + sum_j max(0, Hs_j - He_j)) for a pixel's colour.
double colorFactor(const float* rgb, const DiscreteHistograms& h) {
  if (!h.volumeColors) return 1.0;
  std::array<double, 3> volume, exemplar;
  for (int c = 0; c < 3; ++c) {
    const int bin = h.volumeColors->binOf(rgb[c]);
    volume[c] = h.volumeColors->density(c, bin);
    exemplar[c] = h.exemplarColors->density(c, bin);
  }
  return colorHistogramWeight(1.0, volume, exemplar);
}

/// The histogram re-weighting factor of every exemplar pixel (eq. 4 times eq. 3) as the histograms
/// stand, computed once per batch instead of once per proposal. `withoutOne` is the same with the
/// pixel's count lowered by one: a voxel's own current pixel should not count against keeping it.
struct PixelFactors {
  std::vector<float> factor, withoutOne;
};

PixelFactors pixelFactors(const RgbImage& exemplar, const DiscreteHistograms& h, double scale) {
  const std::size_t pixels = std::size_t(exemplar.pixelCount());
  PixelFactors f;
  f.factor.resize(pixels);
  f.withoutOne.resize(pixels);
  tbb::parallel_for(std::size_t(0), pixels, [&](std::size_t p) {
    const double color = colorFactor(exemplar.data.data() + 3 * p, h);
    const double count = double((*h.position)[p]), theta = scale * (*h.theta)[p];
    f.factor[p] = float(positionHistogramWeight(color, scale * count, theta));
    f.withoutOne[p] = float(positionHistogramWeight(color, scale * (count - 1), theta));
  });
  return f;
}

/// Sorts by pixel and sums the weights of repeated pixels (coherent neighbourhoods propose the
/// same pixel many times), so the choices below work on distinct pixels. Insertion sort: a voxel
/// has a dozen or so proposals, too few for std::sort's machinery to pay off.
void mergeRepeatedPixels(std::vector<Proposal>& proposals) {
  for (std::size_t i = 1; i < proposals.size(); ++i) {
    const Proposal p = proposals[i];
    std::size_t j = i;
    for (; j > 0 && proposals[j - 1].pixel > p.pixel; --j) proposals[j] = proposals[j - 1];
    proposals[j] = p;
  }
  std::size_t out = 0;
  for (std::size_t i = 0; i < proposals.size(); ++i) {
    if (out > 0 && proposals[out - 1].pixel == proposals[i].pixel)
      proposals[out - 1].weight += proposals[i].weight;
    else
      proposals[out++] = proposals[i];
  }
  proposals.resize(out);
}

float squaredColorDistance(const float* a, const float* b) {
  const float d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return d0 * d0 + d1 * d1 + d2 * d2;
}

/// The pixel with the largest summed weight; ties go to the smaller pixel index.
std::int32_t largestVote(const std::vector<Proposal>& merged) {
  std::int32_t best = -1;
  float bestVote = -1;
  for (const Proposal& p : merged)
    if (p.weight > bestVote) {
      bestVote = p.weight;
      best = p.pixel;
    }
  return best;
}

/// The colour kernel of ColourMode: (1 - x/16)^16 for x < 16, else 0, a compact stand-in for
/// exp(-x) (within 0.02 of it everywhere) that costs four squarings instead of a call to exp.
/// Branch-free (the cut-off is a max): which pairs fall beyond it is unpredictable. x/16 is exact,
/// so 1 - x/16 <= 0 exactly when x >= 16.
inline float colorKernel(float x) {
  float k = std::max(0.0f, 1.0f - x * (1.0f / 16.0f));
  k *= k;
  k *= k;
  k *= k;
  return k * k;
}

/// The pixel whose colour gathers the largest weight under the colour kernel; each pair is
/// evaluated once (the kernel is symmetric). The proposals' colours are copied side by side first
/// (the inner loop would otherwise chase exemplar indices), and a's own vote is summed in a
/// register; the additions happen in the same order either way.
std::int32_t colorMode(const std::vector<Proposal>& merged, const RgbImage& exemplar, float invBandwidth,
                       std::vector<float>& votes, std::vector<float>& colors) {
  const std::size_t n = merged.size();
  votes.assign(n, 0.0f);
  colors.resize(3 * n);
  for (std::size_t a = 0; a < n; ++a)
    std::copy_n(exemplar.data.data() + 3 * std::size_t(merged[a].pixel), 3,
                colors.begin() + std::ptrdiff_t(3 * a));
  for (std::size_t a = 0; a < n; ++a) {
    const float* ea = colors.data() + 3 * a;
    const float wa = merged[a].weight;
    float vote = votes[a] + wa * (1.0f + 1e-6f);  // kernel 1 on itself; near-ties: the own weight
    for (std::size_t b = a + 1; b < n; ++b) {
      const float k = colorKernel(squaredColorDistance(ea, colors.data() + 3 * b) * invBandwidth);
      vote += merged[b].weight * k;
      votes[b] += wa * k;
    }
    votes[a] = vote;
  }
  std::size_t best = 0;
  for (std::size_t a = 1; a < n; ++a)
    if (votes[a] > votes[best]) best = a;
  return merged[best].pixel;
}

/// Han et al.'s rule: the proposal nearest in colour to the weighted average of all proposals;
/// ties go to the larger weight.
std::int32_t nearestToAverage(const std::vector<Proposal>& merged, const RgbImage& exemplar) {
  double sum[3] = {0, 0, 0}, total = 0;
  for (const Proposal& p : merged) {
    const float* e = exemplar.data.data() + 3 * std::size_t(p.pixel);
    for (int c = 0; c < 3; ++c) sum[c] += double(p.weight) * e[c];
    total += p.weight;
  }
  const float mean[3] = {float(sum[0] / total), float(sum[1] / total), float(sum[2] / total)};
  std::int32_t best = -1;
  float bestDistance = std::numeric_limits<float>::infinity(), bestWeight = -1;
  for (const Proposal& p : merged) {
    const float d = squaredColorDistance(exemplar.data.data() + 3 * std::size_t(p.pixel), mean);
    if (d < bestDistance || (d == bestDistance && p.weight > bestWeight)) {
      bestDistance = d;
      bestWeight = p.weight;
      best = p.pixel;
    }
  }
  return best;
}

/// Moves the histograms from the sources in `before` to those now in the volume, for one batch.
void refreshHistograms(const WorkVolume& volume, const std::vector<std::int32_t>& before,
                       const RgbImage& exemplar, int batch, const DiscreteHistograms& h) {
  forEachVoxelInBatchSequential(volume.n, batch, [&](const std::array<int, 3>&, std::size_t vi) {
    const std::int32_t now = volume.source[vi], old = before[vi];
    if (now == old) return;
    if (old >= 0) --(*h.position)[old];
    if (now >= 0) ++(*h.position)[now];
    if (h.volumeColors) {
      if (old >= 0) h.volumeColors->add(exemplar.data.data() + 3 * std::size_t(old), -1);
      if (now >= 0) h.volumeColors->add(exemplar.data.data() + 3 * std::size_t(now), +1);
    }
  });
}

}  // namespace

void discreteSolve(WorkVolume& volume, const RgbImage& exemplar, const ExemplarNeighborhoods& ex,
                   const SliceMatches& matches, const DiscreteHistograms& histograms,
                   const DiscreteSolveSettings& settings) {
  const int W = exemplar.width;
  const double exponent = (settings.irlsExponent - 2.0) / 2.0;  // on squared distances
  const double eps = settings.irlsEpsilon * ex.shape.dims();
  const float invBandwidth = float(1.0 / settings.modeBandwidth);
  if (volume.source.size() != volume.count()) volume.source.assign(volume.count(), -1);
  // IRLS weight per matched neighbourhood, computed once.
  std::vector<float> irls(matches.distance.size());
  tbb::parallel_for(std::size_t(0), irls.size(),
                    [&](std::size_t i) { irls[i] = float(std::pow(matches.distance[i] + eps, exponent)); });

  const std::vector<std::int32_t> before = volume.source;
  for (int batch = 0; batch < kParityBatches; ++batch) {
    const PixelFactors factors = pixelFactors(exemplar, histograms, settings.histogramScale);
    forEachVoxelInBatch(volume.n, batch, [&](const std::array<int, 3>& v, std::size_t vi) {
      // One thread-local lookup per voxel (each costs a call in a shared library).
      thread_local VoxelScratch scratch;
      std::vector<Proposal>& proposals = scratch.proposals;
      proposals.clear();
      const std::int32_t current = volume.source[vi];
      forEachCoveringCentre(matches.grid, ex.shape, v, [&](std::size_t id, int i, int j) {
        const std::int32_t m = matches.match[id];
        if (m < 0) return;
        const std::int32_t pixel = (ex.centreY(m) + j) * W + (ex.centreX(m) + i);
        const float factor = pixel == current ? factors.withoutOne[pixel] : factors.factor[pixel];
        proposals.push_back({pixel, irls[id] * factor});
      });
      if (proposals.empty()) return;
      mergeRepeatedPixels(proposals);
      std::int32_t best = -1;
      switch (settings.choice) {
        case ProposalChoice::LargestVote:
          best = largestVote(proposals);
          break;
        case ProposalChoice::ColorMode:
          best = colorMode(proposals, exemplar, invBandwidth, scratch.votes, scratch.colors);
          break;
        case ProposalChoice::NearestToAverage:
          best = nearestToAverage(proposals, exemplar);
          break;
      }
      if (best < 0) return;
      volume.source[vi] = best;
      const float* e = exemplar.data.data() + 3 * std::size_t(best);
      std::copy(e, e + 3, volume.at(vi));
    });
    refreshHistograms(volume, before, exemplar, batch, histograms);
  }
}

}  // namespace solidtex::synthesis::detail

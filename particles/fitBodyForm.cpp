#include "particles/fitBodyForm.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "common/distributionDistance.h"
#include "particles/parseAutoOrNumber.h"
#include "particles/sectionShapes.h"

namespace solidtex {
namespace {

constexpr int kShapesPerCandidate = 96;
constexpr int kPlanesPerShape = 8;
constexpr double kKsTolerance = 0.01;             // KS differences below it are the sections' sampling noise
constexpr std::uint64_t kFitStream = 0x666f726d;  // "form"

}  // namespace

std::optional<double> parseBodyForm(const std::string& text) {
  return parseAutoOrNumber(text, "--body-form", -1, 1);
}

std::vector<double> bodyFormCandidates() { return {-0.5, -0.25, 0, 0.25, 0.5, 0.75, 1}; }

BodyFormFit fitBodyForm(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                        std::uint64_t seed) {
  if (factory.aligned()) return {0, 1};
  const ShapeColumns photo = photoShapes(stats, voxelsPerPixel);
  const std::vector<double> forms = bodyFormCandidates();
  std::vector<BodyFormFit> fits(forms.size());
  tbb::parallel_for(std::size_t(0), forms.size(), [&](std::size_t c) {
    const ParticleFactory candidate = factory.withBodyForm(forms[c]);
    Rng rng(deriveSeed(seed, kFitStream));  // the same particles and planes for every candidate
    const ShapeColumns sections = sectionShapes(stats, candidate, voxelsPerPixel, 1, kShapesPerCandidate,
                                                kPlanesPerShape, SectionAxis::ByExtent, rng);
    fits[c] = {forms[c], ksStatistic(photo.aspect, sections.aspect)};
  });
  // Round sections fit every form alike: the paper's boxes unless another form fits clearly better.
  const double best =
      std::min_element(fits.begin(), fits.end(), [](const BodyFormFit& a, const BodyFormFit& b) {
        return a.aspectKs < b.aspectKs;
      })->aspectKs;
  const BodyFormFit* chosen = nullptr;
  for (const BodyFormFit& fit : fits)
    if (fit.aspectKs <= best + kKsTolerance &&
        (!chosen || std::abs(fit.form) < std::abs(chosen->form) ||
         (std::abs(fit.form) == std::abs(chosen->form) && fit.aspectKs < chosen->aspectKs)))
      chosen = &fit;
  return *chosen;
}

}  // namespace solidtex

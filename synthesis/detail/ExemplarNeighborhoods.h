#pragma once
#include <algorithm>
#include <vector>

#include <Eigen/Core>

#include "synthesis/detail/NeighborhoodShape.h"
#include "synthesis/detail/Pca.h"
#include "synthesis/detail/RgbImage.h"

namespace solidtex::synthesis::detail {

/// Every neighbourhood that lies wholly inside one exemplar level, as full vectors and PCA-reduced.
/// Neighbourhoods are numbered row-major over their valid centres: centre (x, y) with
/// x in [x0, x0 + cols), y in [y0, y0 + rows).
struct ExemplarNeighborhoods {
  NeighborhoodShape shape;
  int exemplarWidth = 0, exemplarHeight = 0;
  int x0 = 0, y0 = 0, cols = 0, rows = 0;
  Eigen::MatrixXf full;  ///< D x M full vectors
  Pca pca;
  std::vector<float> reduced;  ///< M x d, row-major: neighbourhood m's coefficients at m*d

  int count() const { return cols * rows; }
  int reducedDims() const { return pca.dims(); }
  const float* reducedAt(int m) const { return reduced.data() + std::size_t(m) * reducedDims(); }
  int centreX(int m) const { return x0 + m % cols; }
  int centreY(int m) const { return y0 + m / cols; }
  int indexOf(int x, int y) const { return (y - y0) * cols + (x - x0); }
  /// The neighbourhood whose centre is nearest to pixel (x, y) (clamped into the valid range).
  int clampedIndexOf(int x, int y) const {
    return indexOf(std::clamp(x, x0, x0 + cols - 1), std::clamp(y, y0, y0 + rows - 1));
  }
};

/// The full vectors of all neighbourhoods inside `image` (D x M, numbered as ExemplarNeighborhoods).
/// The image must be at least shape.size on both sides.
Eigen::MatrixXf gatherExemplarNeighborhoods(const RgbImage& image, const NeighborhoodShape& shape);

/// Gathers, fits a PCA with `pcaDims` components (clamped to D) and reduces every neighbourhood.
ExemplarNeighborhoods buildExemplarNeighborhoods(const RgbImage& image, const NeighborhoodShape& shape,
                                                 int pcaDims);

}  // namespace solidtex::synthesis::detail

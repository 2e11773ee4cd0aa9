#include "synthesis/detail/ExemplarNeighborhoods.h"

namespace solidtex::synthesis::detail {

Eigen::MatrixXf gatherExemplarNeighborhoods(const RgbImage& image, const NeighborhoodShape& shape) {
  const int x0 = -shape.lo(), y0 = -shape.lo();
  const int cols = image.width - shape.extent() + 1, rows = image.height - shape.extent() + 1;
  // Without wavelet features the block's other pixels are not read: any valid pixel will do.
  const int step = shape.wavelet ? 1 : 0;
  Eigen::MatrixXf out(shape.dims(), std::max(0, cols) * std::max(0, rows));
  for (int cy = 0; cy < rows; ++cy)
    for (int cx = 0; cx < cols; ++cx) {
      float* v = out.col(Eigen::Index(cy) * cols + cx).data();
      for (int j = shape.lo(); j <= shape.hi(); ++j)
        for (int i = shape.lo(); i <= shape.hi(); ++i) {
          const int x = x0 + cx + i, y = y0 + cy + j;
          writePixelFeatures(shape, image.at(x, y), image.at(x + step, y), image.at(x, y + step),
                             image.at(x + step, y + step), v);
        }
    }
  return out;
}

ExemplarNeighborhoods buildExemplarNeighborhoods(const RgbImage& image, const NeighborhoodShape& shape,
                                                 int pcaDims) {
  ExemplarNeighborhoods n;
  n.shape = shape;
  n.exemplarWidth = image.width;
  n.exemplarHeight = image.height;
  n.x0 = -shape.lo();
  n.y0 = -shape.lo();
  n.cols = image.width - shape.extent() + 1;
  n.rows = image.height - shape.extent() + 1;
  n.full = gatherExemplarNeighborhoods(image, shape);
  n.pca = fitPca(n.full, pcaDims);
  const Eigen::MatrixXf reduced = n.pca.projectAll(n.full);  // d x M, column-major = M x d row-major
  n.reduced.assign(reduced.data(), reduced.data() + reduced.size());
  return n;
}

}  // namespace solidtex::synthesis::detail

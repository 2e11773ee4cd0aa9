#pragma once
/// @file
/// The photo's matrix (what lies between its particles) as a texture of its own.

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// Options of matrixExemplar.
struct MatrixExemplarOptions {
  int maxSide = 64;              ///< pixels: the square window of the photo the exemplar is cut from
  int rim = 2;                   ///< pixels around each particle filled too: its shadow and blur
  double minMatrixShare = 0.25;  ///< less matrix than this in the window: no exemplar
};

/// The square window of the photo (side min(maxSide, the photo's shorter side)) that holds the
/// most matrix, its particles and their rims filled by shift-map inpainting (OpenCV xphoto, in
/// CIE Lab), which copies pieces of the matrix into the holes rather than smoothing across them, so
/// the fill keeps the matrix's grain. CV_32FC3 sRGB in [0,1], as synthesizeSolid takes it. Empty
/// when the window holds less matrix than `minMatrixShare`: a dense pile shows too little of it
/// to learn a texture from. Deterministic.
cv::Mat matrixExemplar(const ExemplarStats& stats, const MatrixExemplarOptions& options = {});

}  // namespace solidtex

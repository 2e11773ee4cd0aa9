#pragma once
/// @file
/// The photo's textures apart from its particles' shapes and colours: the matrix between the
/// particles, and the grain inside them, each as a square exemplar for solid synthesis.

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// Options of matrixExemplar and particleExemplar.
struct TextureExemplarOptions {
  int maxSide = 64;        ///< pixels: the square window of the photo the exemplar is cut from
  int rim = 2;             ///< pixels along each particle's outline left out: its shadow and blur
  double minShare = 0.25;  ///< less of the texture than this in the window: no exemplar
};

/// The square window of the photo (side min(maxSide, the photo's shorter side)) that holds the
/// most matrix, each of its particles (with its rim) filled by the piece of matrix around it
/// whose surroundings match the particle's best, so the fill keeps the matrix's grain.
/// CV_32FC3 sRGB in [0,1], as synthesizeSolid takes it. Empty when the window holds less matrix
/// than `minShare`: a dense pile shows too little of it to learn a texture from. Deterministic.
cv::Mat matrixExemplar(const ExemplarStats& stats, const TextureExemplarOptions& options = {});

/// The particles' grain without their colours or shading: the window that holds the most particle
/// pixels (each particle less its rim), each pixel its particle's grain (splitResidual) about a mid
/// grey of linear 0.5, the matrix between them filled with pieces of that grain.
/// CV_32FC3 sRGB in [0,1]. Empty when the window holds less particle than `minShare`.
/// Deterministic.
cv::Mat particleExemplar(const ExemplarStats& stats, const TextureExemplarOptions& options = {});

}  // namespace solidtex

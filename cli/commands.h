#pragma once
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/writeVolumeExports.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/particlePhases.h"

namespace solidtex::cli {

/// A subcommand's action, run after parsing succeeded; returns the exit code.
using Action = std::function<int()>;

/// Each adds its subcommand with its options to `app` and returns what to run when it is chosen.
Action addAnalyzeCommand(CLI::App& app);
Action addParticlesCommand(CLI::App& app, const std::string& commandLine);
Action addCompareCommand(CLI::App& app);
Action addSynthesizeCommand(CLI::App& app, const std::string& commandLine);
Action addSynthesize2dCommand(CLI::App& app);
Action addSpaciousnessCommand(CLI::App& app);
Action addTruthCommand(CLI::App& app);

/// --mask, --invert, --no-split, --min-area: shared by every command that reads a particle photo.
void addSegmentationOptions(CLI::App& command, SegmentationOptions& options);

/// --phases and --phase-mask: kinds of particle (PhaseOptions).
void addPhaseOptions(CLI::App& command, PhaseOptions& options);

/// --tiff, --npy, --vti: shared by every command that writes a volume.
void addExportOptions(CLI::App& command, VolumeExports& exports);

/// --levels, --wavelet-levels, --neighborhoods, --distance: shared by synthesize and synthesize2d.
void addPyramidOptions(CLI::App& command, int& levels, int& waveletLevels, std::vector<int>& neighborhoods,
                       std::string& distance);

}  // namespace solidtex::cli

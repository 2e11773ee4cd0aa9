#include <sched.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <new>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "common/Error.h"
#include "common/ProgressLine.h"
#include "common/ThreadLimit.h"
#include "common/bricksOf.h"
#include "common/memoryBudget.h"
#include "common/secondsSince.h"
#include "io/BrickedVdb.h"
#include "parallel/Communicator.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/synthesizeVolumeJob.h"

namespace solidtex {
namespace {

std::string sides(const Dims& d) {
  return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
}

void checkBrickedJob(const SynthesizeVolumeJob& job) {
  const Dims& d = job.synthesis.dims;
  const int edge = job.brickEdge;
  if (edge < 0) throw OptionError("--bricks must be positive, got " + std::to_string(edge));
  if (edge > 0 && (d.x % edge != 0 || d.y % edge != 0 || d.z % edge != 0))
    throw OptionError("--bricks " + std::to_string(edge) + " does not divide the " + sides(d) +
                      " volume; choose an edge that divides every side");
  if (job.synthesis.region) throw OptionError("--region is one box already; it takes no --bricks");
  if (job.exports.tiff || job.exports.npy || job.exports.vti)
    throw OptionError(
        "--tiff, --npy and --vti hold the whole volume in memory; bricked runs write the .vdb only");
}

// Bricks [first, last) of `count`: contiguous runs, as even as they can be.
std::pair<std::size_t, std::size_t> bricksOfRank(std::size_t count, int rank, int size) {
  return {count * std::size_t(rank) / std::size_t(size), count * std::size_t(rank + 1) / std::size_t(size)};
}

// Threads per process when none are asked for: the cores mpirun bound it to (by default one each
// for up to two processes), else the machine's cores shared by the processes on it. More threads
// than bound cores only take turns.
int threadsPerProcess(int asked) {
  if (asked != 0) return asked;
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  cpu_set_t set;
  CPU_ZERO(&set);
  const int bound = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
  if (bound > 0 && bound < cores) return bound;
  return std::max(1, cores / launchedAs().localSize);
}

// What one process did, sent to rank 0 ahead of its trees.
struct ProcessPart {
  std::size_t bricks = 0;
  double seconds = 0, analysisSeconds = 0;
  std::string error;
  std::string trees;            ///< BrickedVdb::bytes, empty for rank 0 (it keeps its own)
  VolumeSynthesisResult first;  ///< its first brick's statistics and box, no voxels (not sent)
};

std::string encode(const ProcessPart& part) {
  const nlohmann::json header = {{"bricks", part.bricks},
                                 {"seconds", part.seconds},
                                 {"analysis_seconds", part.analysisSeconds},
                                 {"error", part.error}};
  return header.dump() + '\n' + part.trees;
}

ProcessPart decode(std::string&& bytes) {
  const std::size_t end = bytes.find('\n');
  const nlohmann::json header = nlohmann::json::parse(bytes.substr(0, end));
  ProcessPart part{header["bricks"], header["seconds"], header["analysis_seconds"], header["error"], {}};
  part.trees = bytes.substr(end + 1);
  return part;
}

// This process's bricks, made one at a time and joined into `trees`.
ProcessPart makeBricks(const SynthesizeVolumeJob& job, const std::vector<Box>& bricks, int rank, int size,
                       BrickedVdb& trees) {
  ProcessPart part;
  const auto start = std::chrono::steady_clock::now();
  try {
    const DenseVolume exemplar = readVolumeExemplar(job.exemplar);
    const std::optional<FrameField> field = loadVolumeField(job);
    const auto [first, last] = bricksOfRank(bricks.size(), rank, size);
    VolumeSynthesisOptions options = job.synthesis;
    options.field = field ? &*field : nullptr;
    std::size_t current = first;
    ProgressLine progress(job.progress && rank == 0);
    if (job.progress && rank == 0)
      options.progress = [&](const std::string& step, double fraction) {
        progress.update("brick " + std::to_string(current - first + 1) + "/" + std::to_string(last - first) +
                            (size > 1 ? " of rank 0's" : "") + ", " + step,
                        (double(current - first) + fraction) / double(last - first));
      };
    const VolumeSynthesizer synthesizer(exemplar, options);
    for (; current < last; ++current) {
      VolumeSynthesisResult brick = synthesizer.synthesize(bricks[current]);
      part.analysisSeconds = brick.statistics.analysisSeconds;
      if (current == first) part.first = {brick.box, {}, {}, brick.statistics};
      trees.add(solidOfSynthesis(std::move(brick)));
      ++part.bricks;
    }
    progress.done();
  } catch (const std::bad_alloc&) {
    part.error = "out of memory (see --max-memory; smaller bricks need less)";
  } catch (const std::exception& e) {
    part.error = e.what();
  }
  part.seconds = secondsSince(start);
  if (part.error.empty() && rank != 0) part.trees = trees.bytes();
  return part;
}

DenseVolume denseOfSolid(const SolidVolume& solid) {
  if (solid.color.empty()) return {solid.dims, 1, solid.density};
  DenseVolume out{solid.dims, 3, std::vector<float>(solid.color.size() * 3)};
  for (std::size_t i = 0; i < solid.color.size(); ++i)
    std::copy_n(solid.color[i].data(), 3, &out.values[3 * i]);
  return out;
}

Box centralBox(const Dims& d, int side) {
  const Dims c{std::min(d.x, side), std::min(d.y, side), std::min(d.z, side)};
  return Box::at({(d.x - c.x) / 2, (d.y - c.y) / 2, (d.z - c.z) / 2}, c);
}

// Rank 0's seconds after its own bricks: waiting for and receiving the others' trees, joining
// them, and writing the file.
struct RootSeconds {
  double gather = 0, join = 0, write = 0;
};

nlohmann::json bricksReport(const SynthesizeVolumeJob& job, std::size_t count,
                            const std::vector<ProcessPart>& parts, const RootSeconds& root) {
  nlohmann::json processes = nlohmann::json::array();
  double slowest = 0, total = 0;
  std::size_t exchanged = 0;
  for (std::size_t r = 0; r < parts.size(); ++r) {
    const ProcessPart& p = parts[r];
    processes.push_back({{"rank", r},
                         {"bricks", p.bricks},
                         {"seconds", p.seconds},
                         {"analysis_seconds", p.analysisSeconds},
                         {"bytes_sent", p.trees.size()}});
    slowest = std::max(slowest, p.seconds);
    total += p.seconds;
    exchanged += p.trees.size();
  }
  return {{"edge", job.brickEdge > 0
                       ? job.brickEdge
                       : std::max({job.synthesis.dims.x, job.synthesis.dims.y, job.synthesis.dims.z})},
          {"count", count},
          {"processes", parts.size()},
          {"per_process", processes},
          {"bytes_exchanged", exchanged},
          {"load_imbalance", total > 0 ? slowest / (total / double(parts.size())) : 1.0},
          {"gather_seconds", root.gather},
          {"join_seconds", root.join},
          {"write_seconds", root.write}};
}

}  // namespace

nlohmann::json runBrickedVolumeSynthesis(const SynthesizeVolumeJob& job) {
  checkBrickedJob(job);
  const Communicator& world = Communicator::world();
  const bool root = world.rank() == 0;
  const std::vector<Box> bricks = bricksOf(job.synthesis.dims, job.brickEdge);
  // A brick's work as the whole volume's would be (56 bytes a voxel), beside the trees kept so far.
  requireVolumeMemory("synthesising a brick", bricks.front().dims(), 56);
  OutputFiles outputs;
  if (root) {
    outputs.addInput(job.exemplar);
    if (job.field) outputs.addInput(*job.field);
    addVolumeOutputs(outputs, job.output, job.report, job.preview);
  }
  const ThreadLimit threads(threadsPerProcess(job.synthesis.threads));
  BrickedVdb trees;
  const auto start = std::chrono::steady_clock::now();
  ProcessPart mine = makeBricks(job, bricks, world.rank(), world.size(), trees);
  const std::string error = mine.error;
  RootSeconds rootSeconds;
  const auto gatherStart = std::chrono::steady_clock::now();
  std::vector<std::string> gathered = world.gatherToRoot(encode(mine));
  rootSeconds.gather = secondsSince(gatherStart);
  if (!root) {
    if (!error.empty()) throw InputError(error);  // rank 0 says it; this exit code only tells mpirun
    return nlohmann::json::object();
  }
  std::vector<ProcessPart> parts;
  for (std::string& bytes : gathered) parts.push_back(decode(std::move(bytes)));
  for (std::size_t r = 0; r < parts.size(); ++r)
    if (!parts[r].error.empty())
      throw InputError(world.size() > 1 ? "process " + std::to_string(r) + ": " + parts[r].error
                                        : parts[r].error);
  const auto joinStart = std::chrono::steady_clock::now();
  for (std::size_t r = 1; r < parts.size(); ++r) trees.addBytes(parts[r].trees);
  rootSeconds.join = secondsSince(joinStart);

  const DenseVolume exemplar = readVolumeExemplar(job.exemplar);
  nlohmann::json report = volumeSynthesisReport(mine.first, job.synthesis, exemplar,
                                                std::filesystem::path(job.exemplar).filename().string(),
                                                job.field.value_or("none"));
  report["first_brick_level_reports"] = std::move(report["level_reports"]);
  report.erase("level_reports");
  report["analysis_seconds"] = mine.analysisSeconds;
  report["seconds"] = secondsSince(start);

  const Box shown = centralBox(job.synthesis.dims, kBrickedPreviewSide);
  const SolidVolume central = trees.denseBox(shown);
  if (job.measure) report["quality"] = volumeQualityReport(denseOfSolid(central), exemplar, job.quality);
  report["outputs"] = {{"vdb", job.output}};
  if (job.preview) {
    report["outputs"]["previews"] = writeVolumePreviews(outputs, *job.preview, exemplar, central);
    report["outputs"]["preview_box"] = {shown.lo.x, shown.lo.y, shown.lo.z,
                                        shown.hi.x, shown.hi.y, shown.hi.z};
  }
  const auto writeStart = std::chrono::steady_clock::now();
  outputs.write(job.output, [&](const std::string& path) { trees.write(path, volumeFileMetadata(job)); });
  rootSeconds.write = secondsSince(writeStart);
  report["bricks"] = bricksReport(job, bricks.size(), parts, rootSeconds);
  report["peak_memory_mib"] = peakMemoryMiB();
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex

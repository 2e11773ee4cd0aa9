#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "common/Error.h"
#include "common/ProgressLine.h"
#include "common/ThreadLimit.h"
#include "common/bricksOf.h"
#include "common/failureText.h"
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

// What every process checks alike before MPI starts: the same input fails on all of them.
void checkBrickedJob(const SynthesizeVolumeJob& job, int processes) {
  const Dims& d = job.synthesis.dims;
  const int edge = job.brickEdge;
  if (edge < 0) throw OptionError("--bricks must be positive, got " + std::to_string(edge));
  if (edge > 0 && (d.x % edge != 0 || d.y % edge != 0 || d.z % edge != 0))
    throw OptionError("--bricks " + std::to_string(edge) + " does not divide the " + sides(d) +
                      " volume; choose an edge that divides every side");
  if (job.synthesis.region)
    throw OptionError("--region is one box already: it is made neither in bricks nor by several processes");
  if (job.exports.tiff || job.exports.npy || job.exports.vti)
    throw OptionError(
        "--tiff, --npy and --vti hold the whole volume in memory; bricked runs write the .vdb only");
  const std::size_t count = bricksOf(d, edge).size();
  if (count < std::size_t(processes))
    throw OptionError(std::to_string(processes) + " processes for " + std::to_string(count) +
                      " brick(s): give --bricks an edge that makes at least one brick per process");
}

// Bricks [first, last) of `count`: contiguous runs, as even as they can be.
std::pair<std::size_t, std::size_t> bricksOfRank(std::size_t count, int rank, int size) {
  return {count * std::size_t(rank) / std::size_t(size), count * std::size_t(rank + 1) / std::size_t(size)};
}

// Peak bytes of a process: one brick's work as the whole volume's would be (56 a voxel), the trees
// it keeps (at most colour and source, 24 a voxel; rank 0 keeps every process's) and the frame
// field over the whole volume (36 a voxel).
double processPeakBytes(const SynthesizeVolumeJob& job, std::size_t bricks, int rank, int size) {
  const double brick = double(bricksOf(job.synthesis.dims, job.brickEdge).front().dims().count());
  const double whole = double(job.synthesis.dims.count());
  const double kept = rank == 0 ? whole : whole * double(bricks / std::size_t(size) + 1) / double(bricks);
  return 56 * brick + 24 * kept + (job.field ? 36 * whole : 0);
}

// What one process did, sent to rank 0 ahead of its trees.
struct ProcessPart {
  std::size_t bricks = 0;
  double seconds = 0, analysisSeconds = 0;
  std::string failure;          // failureOf, empty when it succeeded
  std::string trees;            // BrickedVdb::bytes; empty for rank 0, which keeps its own
  std::size_t bytesSent = 0;    // the trees' size, kept once they are joined
  VolumeSynthesisResult first;  // its first brick's box and statistics, no voxels (not sent)
};

// The header, a newline, then the trees, which it consumes.
std::string encode(ProcessPart& part) {
  const nlohmann::json header = {{"bricks", part.bricks},
                                 {"seconds", part.seconds},
                                 {"analysis_seconds", part.analysisSeconds},
                                 {"failure", part.failure}};
  std::string bytes = std::move(part.trees);
  bytes.insert(0, header.dump() + '\n');
  return bytes;
}

ProcessPart decode(std::string&& bytes) {
  const std::size_t end = bytes.find('\n');
  const nlohmann::json header = nlohmann::json::parse(bytes.substr(0, end));
  ProcessPart part{
      header["bricks"], header["seconds"], header["analysis_seconds"], header["failure"], {}, 0, {}};
  bytes.erase(0, end + 1);
  part.bytesSent = bytes.size();
  part.trees = std::move(bytes);
  return part;
}

// This process's bricks, made one at a time and joined into `trees`; other ranks' as bytes.
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
    if (rank != 0) {
      part.trees = trees.bytes();
      trees = BrickedVdb();
    }
  } catch (...) {
    part.failure = failureText(std::current_exception());
  }
  part.seconds = secondsSince(start);
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
                         {"bytes_sent", p.bytesSent}});
    slowest = std::max(slowest, p.seconds);
    total += p.seconds;
    exchanged += p.bytesSent;
  }
  const Dims& d = job.synthesis.dims;
  return {{"edge", job.brickEdge > 0 ? job.brickEdge : std::max({d.x, d.y, d.z})},
          {"count", count},
          {"processes", parts.size()},
          {"per_process", processes},
          {"bytes_exchanged", exchanged},
          {"load_imbalance", total > 0 ? slowest / (total / double(parts.size())) : 1.0},
          {"gather_seconds", root.gather},
          {"join_seconds", root.join},
          {"write_seconds", root.write}};
}

// On rank 0: every part, its own first, joined into `trees` as each is read; the first failure
// thrown instead.
std::vector<ProcessPart> joinParts(std::vector<std::string>&& gathered, ProcessPart&& own, BrickedVdb& trees,
                                   RootSeconds& seconds) {
  std::vector<ProcessPart> parts;
  parts.push_back(std::move(own));
  for (std::size_t r = 1; r < gathered.size(); ++r) parts.push_back(decode(std::move(gathered[r])));
  for (std::size_t r = 0; r < parts.size(); ++r)
    if (!parts[r].failure.empty())
      throwFailureText(r == 0 ? parts[r].failure
                              : parts[r].failure.substr(0, 1) + "process " + std::to_string(r) + ": " +
                                    parts[r].failure.substr(1));
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t r = 1; r < parts.size(); ++r) {
    trees.addBytes(parts[r].trees);
    std::string().swap(parts[r].trees);
  }
  seconds.join = secondsSince(start);
  return parts;
}

// Rank 0's files: the report, previews and quality from the central box, and the joined .vdb.
nlohmann::json writeBrickedOutputs(const SynthesizeVolumeJob& job, OutputFiles& outputs, BrickedVdb& trees,
                                   const std::vector<ProcessPart>& parts, std::size_t bricks,
                                   RootSeconds& seconds, double elapsed) {
  const DenseVolume exemplar = readVolumeExemplar(job.exemplar);
  nlohmann::json report = volumeSynthesisReport(parts.front().first, job.synthesis, exemplar,
                                                std::filesystem::path(job.exemplar).filename().string(),
                                                job.field.value_or("none"));
  report["first_brick_level_reports"] = std::move(report["level_reports"]);
  report.erase("level_reports");
  report["analysis_seconds"] = parts.front().analysisSeconds;
  report["seconds"] = elapsed;
  const Box shown = centralBox(job.synthesis.dims, kBrickedPreviewSide);
  const SolidVolume central = trees.denseBox(shown);
  if (job.measure) report["quality"] = volumeQualityReport(denseOfSolid(central), exemplar, job.quality);
  report["outputs"] = {{"vdb", job.output}};
  if (job.preview) {
    report["outputs"]["previews"] = writeVolumePreviews(outputs, *job.preview, exemplar, central);
    report["outputs"]["preview_box"] = {shown.lo.x, shown.lo.y, shown.lo.z,
                                        shown.hi.x, shown.hi.y, shown.hi.z};
  }
  const auto start = std::chrono::steady_clock::now();
  outputs.write(job.output, [&](const std::string& path) { trees.write(path, volumeFileMetadata(job)); });
  seconds.write = secondsSince(start);
  report["bricks"] = bricksReport(job, bricks, parts, seconds);
  report["peak_memory_mib"] = peakMemoryMiB();
  writeReport(outputs, job.report, report);
  return report;
}

}  // namespace

nlohmann::json runBrickedVolumeSynthesis(const SynthesizeVolumeJob& job) {
  checkBrickedJob(job, launchedAs().size);
  const Communicator& world = Communicator::world();
  const bool root = world.rank() == 0;
  const std::vector<Box> bricks = bricksOf(job.synthesis.dims, job.brickEdge);
  // Checks that may fail on one process alone (its memory, rank 0's outputs) are agreed on before
  // the work: a process that left alone would leave the others waiting for it.
  OutputFiles outputs;
  std::string failure;
  try {
    requireMemory("synthesising bricks", processPeakBytes(job, bricks.size(), world.rank(), world.size()));
    if (root) {
      outputs.addInput(job.exemplar);
      if (job.field) outputs.addInput(*job.field);
      addVolumeOutputs(outputs, job.output, job.report, job.preview);
    }
  } catch (...) {
    failure = failureText(std::current_exception());
  }
  if (const std::string first = world.firstOf(failure); !first.empty()) throwFailureText(first);

  const ThreadLimit threads(threadsPerProcess(job.synthesis.threads));
  BrickedVdb trees;
  const auto start = std::chrono::steady_clock::now();
  ProcessPart mine = makeBricks(job, bricks, world.rank(), world.size(), trees);
  RootSeconds seconds;
  const auto gatherStart = std::chrono::steady_clock::now();
  const std::string myFailure = mine.failure;
  std::vector<std::string> gathered = world.gatherToRoot(encode(mine));
  seconds.gather = secondsSince(gatherStart);
  if (!root) {
    if (!myFailure.empty()) throwFailureText(myFailure);  // rank 0 says it; this exit code only tells mpirun
    return nlohmann::json::object();
  }
  const std::vector<ProcessPart> parts = joinParts(std::move(gathered), std::move(mine), trees, seconds);
  nlohmann::json report =
      writeBrickedOutputs(job, outputs, trees, parts, bricks.size(), seconds, secondsSince(start));
  outputs.commit();
  return report;
}

}  // namespace solidtex

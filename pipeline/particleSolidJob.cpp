#include "pipeline/particleSolidJob.h"

#include <functional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "common/Error.h"
#include "common/failureText.h"
#include "common/memoryBudget.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "mesh/meshTopology.h"
#include "mesh/writeParticleMeshes.h"
#include "parallel/Communicator.h"
#include "particleSolid/particleSolidReport.h"
#include "pipeline/compareJob.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/planePixelSizes.h"
#include "pipeline/warnOfDroppedRegions.h"
#include "validation/arrangement.h"
#include "validation/compareSections.h"
#include "voxel/writePreviews.h"

namespace solidtex {
namespace {

// The xz and yz photos, one standing for both.
void analyzePlanePhotos(const ParticleSolidJob& job, ParticleSolidBuilder& builder) {
  if (!job.photoXz && !job.photoYz) {
    if (!job.pixelSizes.empty() || job.pixelSizesFromFiles)
      throw OptionError(
          "--pixel-sizes brings three planes' photos to one scale: give --photo-xz or --photo-yz");
    return;
  }
  const std::string xzPath = job.photoXz.value_or(*job.photoYz), yzPath = job.photoYz.value_or(*job.photoXz);
  cv::Mat xz = loadPhoto(xzPath), yz = xzPath == yzPath ? xz : loadPhoto(yzPath);
  if (const auto sizes =
          planePixelSizes(job.pixelSizes, {job.photo, xzPath, yzPath}, job.pixelSizesFromFiles)) {
    const double side = squarePixelSide((*sizes)[0], job.photo);
    const bool oneForBoth = xz.data == yz.data;
    xz = atPixelSize(xz, (*sizes)[1], side, xzPath);
    yz = oneForBoth && (*sizes)[1] == (*sizes)[2] ? xz : atPixelSize(yz, (*sizes)[2], side, yzPath);
  }
  builder.analyzePlanes(xz, xzPath, yz, yzPath);
}

nlohmann::json meshReport(OutputFiles& outputs, const std::string& path,
                          const std::vector<ParticleMesh>& meshes) {
  std::size_t triangles = 0;
  for (const ParticleMesh& m : meshes) triangles += m.surface.triangles.size();
  const int closed = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, meshes.size()), 0,
      [&](const tbb::blocked_range<std::size_t>& range, int count) {
        for (std::size_t i = range.begin(); i < range.end(); ++i)
          count += meshTopology(meshes[i].surface).closed;
        return count;
      },
      std::plus<>());
  const std::vector<std::string> files = writeParticleMeshes(outputs, path, meshes);
  return {{"path", path},
          {"files", files.size()},
          {"particles", meshes.size()},
          {"triangles", triangles},
          {"closed_manifold", closed}};
}

}  // namespace

nlohmann::json runParticleSolid(const ParticleSolidJob& job) {
  if (launchedAs().size > 1 && job.brickEdge <= 0)
    throw OptionError("mpirun's processes share particle placement in bricks only: give --bricks");
  const Communicator& world = Communicator::world();
  const bool root = world.rank() == 0;
  ProgressLine line(job.progress && root);
  ParticleSolidOptions options = job;
  options.meshes = job.meshPath.has_value();
  options.denseColor = job.exports.tiff || job.exports.npy || job.exports.vti;
  options.timePlacement = job.progress;
  if (world.size() > 1)
    options.brickTeam = {world.rank(), world.size(),
                         [&world](std::string bytes) { return world.allGather(std::move(bytes)); }};
  // Checks that may fail on one process alone (rank 0's outputs) are agreed on before the work: a
  // process that left alone would leave the others waiting for it.
  OutputFiles outputs;
  std::optional<ParticleSolidBuilder> builder;
  std::string failure;
  try {
    builder.emplace(options, [&](const std::string& step, double fraction) { line.update(step, fraction); });
    if (root) {
      outputs.addInput(job.photo);
      for (const auto& plane : {job.photoXz, job.photoYz})
        if (plane) outputs.addInput(*plane);
      if (job.segmentation.maskPath) outputs.addInput(*job.segmentation.maskPath);
      if (job.phases.maskPath) outputs.addInput(*job.phases.maskPath);
      addVolumeOutputs(outputs, job.output, job.report, job.preview);
      addVolumeExports(outputs, job.exports);
      if (job.meshPath) addParticleMeshes(outputs, "--meshes", *job.meshPath);
    }
  } catch (...) {
    if (world.size() == 1) throw;
    failure = failureText(std::current_exception());
  }
  if (const std::string first = world.firstOf(failure); !first.empty()) throwFailureText(first);

  cv::Mat photo;
  try {
    photo = loadPhoto(job.photo);
    const ExemplarStats& stats = builder->analyze(photo, job.photo);
    if (root) warnOfDroppedRegions(stats, &line);
    analyzePlanePhotos(job, *builder);
    builder->makeParticles();
    builder->place();
  } catch (...) {
    if (world.size() == 1) throw;
    failure = failureText(std::current_exception());
  }
  // The processes meet the same input alike (and a brick's failure reaches every one with its
  // bytes): they agree here, so that none exits while another still works, which mpirun reports.
  if (const std::string first = world.firstOf(failure); !first.empty()) throwFailureText(first);
  line.done();
  if (!root) return nlohmann::json::object();  // rank 0 paints and writes the whole placement
  ParticleSolid solid = builder->finish();
  solid.volume.metadata = particleSolidMetadata(solid, job, job.commandLine);

  solid.timer.start("write");
  line.update("writing the outputs");
  nlohmann::json written = {{"vdb", job.output}};
  if (job.meshPath) written["meshes"] = meshReport(outputs, *job.meshPath, solid.meshes);
  if (job.preview) written["previews"] = writePreviews(outputs, *job.preview, photo, solid.volume);
  // Exports are dense arrays: their colours are painted whole, which the .vdb alone does not need.
  if (options.denseColor) paintColor(solid.volume);
  // A voxel is 1 / scale of the photo's pixels, whose size in µm a user may know.
  const auto exported =
      writeVolumeExports(outputs, job.exports, solid.volume, {1 / solid.voxelsPerPixel, "pixel"});
  if (!exported.empty()) written["exports"] = exported;
  nlohmann::json report = particleSolidReport(solid, options);
  if (solid.bricks) {
    const double scale = solid.voxelsPerPixel;
    const int window = arrangementWindowSide(meanParticleDiameter(solid.stats) * scale, solid.volume.dims,
                                             photoLabels(solid.stats, scale).size());
    report["bricks"]["seams"] =
        brickSeamsReport(solid.volume.particleId, solid.volume.dims, job.brickEdge, window);
  }
  outputs.write(job.output, [&](const std::string& path) { writeVdb(path, std::move(solid.volume)); });

  report["outputs"] = written;
  report["time_seconds"] = solid.timer.finish();
  report["peak_memory_mib"] = peakMemoryMiB();
  report["memory_estimate_mib"] = solid.memoryEstimate / (1024.0 * 1024.0);
  writeReport(outputs, job.report, report);
  outputs.commit();
  line.done();
  return report;
}

}  // namespace solidtex

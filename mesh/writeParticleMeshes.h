#pragma once
/// @file
/// Particle meshes as files: one PLY with vertex colours and particle ids, or one OBJ with an object
/// and an MTL material per particle.

#include <span>
#include <string>
#include <vector>

#include "common/OutputFiles.h"
#include "mesh/ParticleMesh.h"

namespace solidtex {

/// Declares `path` with `outputs` for option `option`: a `.ply` or `.obj` file, and the `.mtl`
/// beside an OBJ.
void addParticleMeshes(OutputFiles& outputs, const std::string& option, const std::string& path);

/// Writes the meshes as `addParticleMeshes` declared them, through `outputs`; returns the paths.
std::vector<std::string> writeParticleMeshes(OutputFiles& outputs, const std::string& path,
                                             const std::vector<ParticleMesh>& meshes);

/// Binary little-endian PLY: vertices with sRGB `red green blue` and `particle_id`, faces with
/// `particle_id`.
void writePly(const std::string& path, std::span<const ParticleMesh> meshes);

/// Wavefront OBJ: an object `particle_<id>` per particle using material `particle_<id>`, whose `Kd`
/// (linear RGB, as Blender reads it) is in `mtlPath`, named in the OBJ by its file name `mtlName`.
void writeObj(const std::string& path, const std::string& mtlName, std::span<const ParticleMesh> meshes);
void writeMtl(const std::string& path, std::span<const ParticleMesh> meshes);

}  // namespace solidtex

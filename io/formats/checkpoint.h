// Binary checkpoints of a DEM World that continue bit-identically after loading.
#pragma once

#include "dem/core/world.h"
#include "dem/run/stage_store.h"

#include <cstdint>
#include <string>

namespace clumpkit {

/// Current checkpoint format version (bumped on any layout change, or a change in what a
/// stored word means: 4 = run_until's height reference is the one after the window test;
/// 6 = the sort interval, WorldOptions::sort_every; 7 = the stage state as key/value text; 8 = each
/// body's zone after its diameter; 9 = the cohesive law and the corner stiffness after the
/// contact parameters, each body's corners after its zone, the bonds after the walls, the corner
/// contacts after the wall contacts; 10 = the cohesive law's friction after its fracture energies,
/// each bond point's crack slip after its damage; 11 = the same layout, written by an engine that
/// sums each body's pair contacts in the contact pass, chunk by chunk: a run resumed from an
/// older file would not continue the bits of the run that wrote it, so none is read; 13 = the skin
/// list holds the pairs of bonded bodies, which the near filter leaves out: an older list lacks
/// the pairs a breaking bond frees; 14 = each contact's excused overlap after its shear; 15 =
/// whether broken bonds act, WorldOptions::broken_bonds_act, after the corner stiffness). Only the
/// current version is read; any other is refused naming both versions.
inline constexpr std::uint32_t kCheckpointVersion = 15;

/// Writes `world` and `info` to `path`: magic "CLUMPKITCKPT", version, the stage and its state
/// (length-prefixed strings: the stage, the number of entries, each key and value), then
/// little-endian
/// integers and raw IEEE-754 doubles — options (gravity, timestep, skin, near-skin fraction,
/// sort interval, contact parameters, cohesive law, corner stiffness, whether broken bonds act),
/// step count, time, every body (spheres, mass, moments, position, velocity, orientation, angular
/// velocity, force, torque, rotation lock, volume, kind, template id, scale, diameter, zone,
/// corners), walls (moving planes with their current point), bonds (bodies, normal, strength
/// factor, points in both frames with area and damage and crack slip), pair, wall and corner
/// contacts with their full state (shear history included), the neighbour lists (build positions
/// and pairs, filter positions and limit) and a trailing FNV-1a 64 checksum. Written atomically
/// (write_file_atomically), so a reader never sees a partial file. Throws IoError when the file
/// cannot be written.
void save_checkpoint(const std::string& path, const dem::World& world,
                     const dem::CheckpointInfo& info = {});

/// Reads a checkpoint written by save_checkpoint into a new world whose later steps are
/// bit-identical to those of the saved one; fills `info` when given. Throws IoError when the
/// file cannot be opened, and InvalidInput naming the file for a wrong magic or version, a
/// truncated or over-long file, a checksum mismatch or inconsistent content.
dem::World load_checkpoint(const std::string& path, dem::CheckpointInfo* info = nullptr);

}  // namespace clumpkit

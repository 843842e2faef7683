// Checkpoints: the film's raw totals plus what identifies the render (scene
// content hash, settings, seed, integrator and parameters), so a render
// killed at any moment continues with --resume and ends bit for bit as an
// uninterrupted one. Binary, little-endian, written atomically.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include "lancer/host/film.h"

namespace lancer {

class CheckpointError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// What must match for a checkpoint to be resumed: every key's value.
// Conventionally scene_hash, width, height, seed, integrator, parameters,
// crop, spp, noise.
using CheckpointIdentity = std::map<std::string, std::string>;

// "<output>.lancer-checkpoint", beside the output image.
std::string checkpoint_path_for(const std::string& output);

// 64-bit FNV-1a of a file's bytes as 16 hex digits; throws CheckpointError
// if unreadable.
std::string content_hash_of_file(const std::string& path);

// Atomic: a temporary beside the target, fsync, rename. Throws
// CheckpointError naming the path on failure.
void write_checkpoint(const std::string& path, const CheckpointIdentity& identity, const Film& film);

// Loads into `film` (already sized for the render). Throws CheckpointError
// with a message naming every identity field that differs, or what is wrong
// with the file (missing, truncated, not a checkpoint, another size).
void read_checkpoint(const std::string& path, const CheckpointIdentity& expected, Film& film);

}  // namespace lancer

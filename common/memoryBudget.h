#pragma once
/// @file memoryBudget.h
/// @brief Refusing work up front that would not fit in memory.
#include <cstdint>
#include <string>

#include "common/Grid.h"

namespace solidtex {

/// Bytes this process may still allocate: the least of the system's available memory, the
/// cgroup's limit less its usage, the address-space and data limits (ulimit -v, -d) less what is
/// mapped, and the limit set by setMemoryLimit.
std::uint64_t availableMemoryBytes();

/// Caps availableMemoryBytes at `bytes` for the rest of the process (--max-memory); 0 removes the cap.
void setMemoryLimit(std::uint64_t bytes);

/// Parses a size such as "8G", "512M", "1.5GiB" or "1000000" (bytes); throws InputError otherwise.
std::uint64_t parseMemorySize(const std::string& text);

/// Throws InputError "`what` needs N GiB of memory, M GiB available" when `bytes` exceed
/// availableMemoryBytes(). Callers pass an estimate of their peak before allocating it.
void requireMemory(const std::string& what, double bytes);

/// Refuses (InputError), before any of it is allocated, a volume of `dims` that needs more memory
/// than there is: `bytesPerVoxel` is the work's measured peak per voxel (docs/performance.md),
/// plus what every run holds (libraries, the photo). Also refuses (OptionError) more voxels than
/// 32-bit indices reach.
void requireVolumeMemory(const std::string& what, const Dims& dims, double bytesPerVoxel);

/// requireVolumeMemory for work whose peak, `bytes` in all, is estimated by its own model.
void requireVolumeBytes(const std::string& what, const Dims& dims, double bytes);

/// Hands the memory this process has freed back to the system. The C library keeps freed blocks for
/// reuse, and after millions of small ones (a placement's buckets) that can be gigabytes the next
/// large allocation does not reuse.
void returnFreedMemory();

/// Peak resident memory of this process so far, in MiB.
double peakMemoryMiB();

/// Lets allocations of this process fail (std::bad_alloc) once it maps `bytes` more than when the
/// cap was made, until the cap is destroyed: third-party code given damaged input can ask for
/// memory without end. Has no effect in sanitizer builds, whose shadow memory an address-space
/// limit would break.
class MemoryCap {
public:
  explicit MemoryCap(std::uint64_t bytes);
  ~MemoryCap();
  MemoryCap(const MemoryCap&) = delete;
  MemoryCap& operator=(const MemoryCap&) = delete;

private:
  bool active_ = false;
  std::uint64_t previous_ = 0;
};

/// "1.5 GiB", "300 MiB": a byte count as a person reads it.
std::string formatBytes(double bytes);

}  // namespace solidtex

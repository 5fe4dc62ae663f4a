// penumbraProcessMemory.h: this process's resident memory, shared by PenumbraLoad and the tests
// that check the pass does not keep memory it no longer needs. Header-only, Linux (/proc).
#ifndef penumbraProcessMemory_h
#define penumbraProcessMemory_h

#include <malloc.h> // malloc_trim: give freed heap back so VmRSS tracks what is live

#include <cstdlib>
#include <fstream>
#include <string>

namespace penumbra
{

/// VmRSS and VmHWM in MiB, -1 where /proc cannot tell.
struct ProcessMemory
{
  double RssMiB = -1.0;
  double HwmMiB = -1.0;
};

inline ProcessMemory ReadProcessMemory()
{
  // Freed heap stays in RSS until glibc trims it: trim first, so RSS is what is live.
  malloc_trim(0);
  ProcessMemory memory;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
  {
    const bool rss = line.rfind("VmRSS:", 0) == 0, hwm = line.rfind("VmHWM:", 0) == 0;
    if (rss || hwm)
    {
      const double kib = std::strtod(line.c_str() + 6, nullptr);
      (rss ? memory.RssMiB : memory.HwmMiB) = kib / 1024.0;
    }
  }
  return memory;
}

} // namespace penumbra

#endif

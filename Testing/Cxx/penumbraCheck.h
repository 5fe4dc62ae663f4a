// The checks every C++ test here reports with: one line per check, a failure count, an exit code.
#ifndef penumbraCheck_h
#define penumbraCheck_h

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace penumbra_test
{

inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline void Check(bool condition, const std::string& what)
{
  std::printf("%s: %s\n", condition ? "ok  " : "FAIL", what.c_str());
  if (!condition)
  {
    ++Failures();
  }
}

/// The larger of `worst` and `value`, NaN once either is: std::max drops a NaN in its second
/// argument, and a NaN result would then pass the check on the worst.
inline double Worse(double worst, double value)
{
  return std::isnan(value) || value > worst ? value : worst;
}

/// Prints the verdict and returns the process's exit code.
inline int Finish()
{
  std::printf("%s: %d failure(s)\n", Failures() ? "FAILED" : "passed", Failures());
  return Failures() ? 1 : 0;
}

/// A test program's features by name: ctest runs each as its own entry (<Program>.<name>, read
/// from the table by Testing/Cxx/CMakeLists.txt), so that a failure names what broke.
using Features = std::vector<std::pair<std::string, void (*)()>>;

/**
 * Runs the feature named by argv[1], or every one without an argument. `--count N` checks that
 * the table has N features: CMake registers them by reading the source, and this entry fails if
 * it missed one.
 */
inline int RunFeatures(int argc, char* argv[], const Features& features)
{
  if (argc == 3 && std::string(argv[1]) == "--count")
  {
    Check(features.size() == static_cast<std::size_t>(std::atoi(argv[2])),
      "ctest has an entry for each of the " + std::to_string(features.size()) + " features");
    return Finish();
  }
  bool found = argc < 2;
  for (const auto& feature : features)
  {
    if (argc < 2 || feature.first == argv[1])
    {
      feature.second();
      found = true;
    }
  }
  if (!found)
  {
    std::fprintf(stderr, "unknown feature %s; the features are:", argv[1]);
    for (const auto& feature : features)
    {
      std::fprintf(stderr, " %s", feature.first.c_str());
    }
    std::fprintf(stderr, "\n");
    return 2;
  }
  return Finish();
}

} // namespace penumbra_test

#endif

// The checks every C++ test here reports with: one line per check, a failure count, an exit code.
#ifndef penumbraCheck_h
#define penumbraCheck_h

#include <cstdio>
#include <string>

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

/// Prints the verdict and returns the process's exit code.
inline int Finish()
{
  std::printf("%s: %d failure(s)\n", Failures() ? "FAILED" : "passed", Failures());
  return Failures() ? 1 : 0;
}

} // namespace penumbra_test

#endif

// One table-driven command-line parser for every program of the project (the demo, the
// benchmarks, the load test, the hard-case suite and the fuzz driver): each lists its options
// and what each does with its value; parsing, help, and the errors for a missing value, an
// unknown option or a bad value are written once, here. Needs nothing but the standard library.
#ifndef penumbraOptions_h
#define penumbraOptions_h

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace penumbra
{
namespace bench
{

/// The non-empty items of a comma-separated list.
inline std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');)
  {
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}

/// Parses a whole string as an integer in [minimum, maximum]; false (value untouched) otherwise.
inline bool ParseInt(const char* text, int minimum, int maximum, int& value)
{
  char* end = nullptr;
  const long parsed = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || parsed < minimum || parsed > maximum)
  {
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

/// Parses a whole string as a finite number >= minimum; false (value untouched) otherwise.
inline bool ParseDouble(const char* text, double minimum, double& value)
{
  char* end = nullptr;
  const double parsed = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(parsed) || parsed < minimum)
  {
    return false;
  }
  value = parsed;
  return true;
}

/// One option: its name (and an optional short alias), and what it does with its value. A
/// flag takes no value (Take receives nullptr). Take returns false for a bad value.
struct Option
{
  std::string Name;
  std::string Alias;
  bool Flag = false;
  std::function<bool(const char* value)> Take;
};

/// A flag that runs `set`.
inline Option FlagOption(const std::string& name, std::function<void()> set)
{
  return { name, "", true,
    [set](const char*)
    {
      set();
      return true;
    } };
}

/// An option whose value `take` parses.
inline Option ValueOption(
  const std::string& name, std::function<bool(const char*)> take, const std::string& alias = "")
{
  return { name, alias, false, std::move(take) };
}

/// An integer in [minimum, maximum]; `given` (if any) is set when the option appears.
inline Option IntOption(
  const std::string& name, int minimum, int maximum, int& target, bool* given = nullptr)
{
  return ValueOption(name,
    [minimum, maximum, &target, given](const char* value)
    {
      if (given)
      {
        *given = true;
      }
      return ParseInt(value, minimum, maximum, target);
    });
}

/// A finite number >= minimum; `given` (if any) is set when the option appears.
inline Option DoubleOption(
  const std::string& name, double minimum, double& target, bool* given = nullptr)
{
  return ValueOption(name,
    [minimum, &target, given](const char* value)
    {
      if (given)
      {
        *given = true;
      }
      return ParseDouble(value, minimum, target);
    });
}

/// Any text.
inline Option TextOption(
  const std::string& name, std::string& target, const std::string& alias = "")
{
  return ValueOption(
    name,
    [&target](const char* value)
    {
      target = value;
      return true;
    },
    alias);
}

/// A comma-separated, non-empty list; with `known`, every item must be one of them.
inline Option ListOption(const std::string& name, std::vector<std::string>& target,
  const std::vector<std::string>* known = nullptr)
{
  return ValueOption(name,
    [name, &target, known](const char* value)
    {
      target = SplitList(value);
      bool ok = !target.empty();
      for (const std::string& item : target)
      {
        if (known && std::find(known->begin(), known->end(), item) == known->end())
        {
          std::fprintf(stderr, "unknown %s '%s'\n", name.c_str() + 2, item.c_str());
          ok = false;
        }
      }
      return ok;
    });
}

/**
 * Parses argv against `table`. -h and --help print `usage` and exit; a missing value, an
 * unknown option or a bad value is reported on stderr, prefixed with the program's name, and
 * returns false. An argument that does not start with '-' goes to `positional` where the
 * program takes some (input files), and is an error otherwise.
 */
inline bool ParseOptions(int argc, char* argv[], const std::vector<Option>& table,
  void (*usage)(const char* program),
  const std::function<void(const char* argument)>& positional = nullptr)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      usage(argv[0]);
      std::exit(EXIT_SUCCESS);
    }
    if (positional && arg.compare(0, 1, "-") != 0)
    {
      positional(argv[i]);
      continue;
    }
    const auto option = std::find_if(table.begin(), table.end(),
      [&](const Option& o) { return o.Name == arg || (!o.Alias.empty() && o.Alias == arg); });
    if (option == table.end())
    {
      std::fprintf(stderr, "%s: unknown option %s\n", argv[0], arg.c_str());
      return false;
    }
    if (option->Flag)
    {
      option->Take(nullptr);
      continue;
    }
    if (i + 1 >= argc)
    {
      std::fprintf(stderr, "%s: missing value after %s\n", argv[0], arg.c_str());
      return false;
    }
    const char* value = argv[++i];
    if (!option->Take(value))
    {
      std::fprintf(stderr, "%s: bad value '%s' for %s\n", argv[0], value, arg.c_str());
      return false;
    }
  }
  return true;
}

} // namespace bench
} // namespace penumbra

#endif

// Stand-alone driver for LLVMFuzzerTestOneInput where libFuzzer is not available (g++ builds):
// replays every corpus file given, then runs pseudo-random and mutated inputs from a fixed seed,
// so the ctest smoke test is reproducible. A failed invariant aborts inside the target; the
// driver names the input and leaves it in --crash-dir (default: the working directory).
//
//   penumbraGeometryFuzzSmoke [--runs N] [--seed S] [--max-len L] [--crash-dir DIR]
//                             [--write-seeds DIR] [FILE|DIR]...
#include "penumbraFuzzInput.h"
#include "penumbraOptions.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{
namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
using penumbra::fuzz::ByteWriter;

std::string CrashDir = ".";
std::string CurrentLabel;
std::string CurrentPath;
const Bytes* CurrentInput = nullptr;

void WriteAll(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while (size > 0)
  {
    const ssize_t written = ::write(fd, p, size);
    if (written <= 0)
    {
      return;
    }
    p += written;
    size -= static_cast<std::size_t>(written);
  }
}

/// An invariant failure aborts inside the target: save the input and say which one it was
/// (plain write(2) calls: this runs in a signal handler).
extern "C" void OnAbort(int)
{
  const int fd = ::open(CurrentPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0 && CurrentInput)
  {
    WriteAll(fd, CurrentInput->data(), CurrentInput->size());
    ::close(fd);
  }
  const char* parts[] = { "penumbraGeometryFuzzSmoke: failed on ", CurrentLabel.c_str(),
    ", saved as ", CurrentPath.c_str(), "\n" };
  for (const char* part : parts)
  {
    WriteAll(2, part, std::strlen(part));
  }
  std::signal(SIGABRT, SIG_DFL);
  std::abort();
}

void Run(const Bytes& input, const std::string& label)
{
  CurrentInput = &input;
  CurrentLabel = label;
  LLVMFuzzerTestOneInput(input.data(), input.size());
  CurrentInput = nullptr;
}

Bytes ReadFile(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteFile(const fs::path& path, const Bytes& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

/// libFuzzer-like mutations: flip, overwrite, insert, erase, truncate, splice.
Bytes Mutate(
  Bytes input, const std::vector<Bytes>& corpus, std::mt19937& rng, std::size_t maxLength)
{
  const int steps = 1 + static_cast<int>(rng() % 8);
  for (int s = 0; s < steps; ++s)
  {
    const std::size_t at = input.empty() ? 0 : rng() % input.size();
    switch (rng() % 6)
    {
      case 0:
        if (!input.empty())
        {
          input[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        }
        break;
      case 1:
        if (!input.empty())
        {
          input[at] = static_cast<std::uint8_t>(rng());
        }
        break;
      case 2:
        input.insert(
          input.begin() + static_cast<std::ptrdiff_t>(at), static_cast<std::uint8_t>(rng()));
        break;
      case 3:
        if (!input.empty())
        {
          input.erase(input.begin() + static_cast<std::ptrdiff_t>(at));
        }
        break;
      case 4:
        input.resize(at);
        break;
      default:
      {
        const Bytes& other = corpus[rng() % corpus.size()];
        if (!other.empty())
        {
          const std::size_t from = rng() % other.size();
          input.resize(at);
          input.insert(input.end(), other.begin() + static_cast<std::ptrdiff_t>(from), other.end());
        }
      }
    }
  }
  if (input.size() > maxLength)
  {
    input.resize(maxLength);
  }
  return input;
}

// Hand-made seeds: ordinary scenes the mutations start from, and the regressions.
/// The header of a raw-caster scene under a positional light: flags 0 (a caller may change
/// Bytes[0]), light kind 1.
ByteWriter PositionalLight(double x, double y, double z, double radius)
{
  ByteWriter w;
  w.U8(0).U8(1);
  w.Scalar(x).Scalar(y).Scalar(z).Scalar(radius);
  return w;
}

void CubeCorners(ByteWriter& w)
{
  for (int k = 0; k < 8; ++k)
  {
    w.Lattice(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
  }
}

void Receivers(ByteWriter& w)
{
  w.U8(4);
  w.U8(0).U8(128).Scalar(0.5);    // beyond the middle of each edge
  w.U8(0).U8(10).Scalar(2.0);     // beyond one end
  w.U8(1).Point(0.25, -3.0, 0.5); // on the ground
  w.U8(1).Lattice(0, 0, 0);       // inside the caster
  w.U8(8).Point(0, 0, 0);         // light samples towards the origin
}

std::vector<std::pair<std::string, Bytes>> Seeds()
{
  // Closed cube (12 outward triangles) as raw triangles.
  static const int cube[12][3] = { { 0, 2, 1 }, { 1, 2, 3 }, { 4, 5, 6 }, { 5, 7, 6 }, { 0, 1, 4 },
    { 1, 5, 4 }, { 2, 6, 3 }, { 3, 6, 7 }, { 0, 4, 2 }, { 2, 4, 6 }, { 1, 3, 5 }, { 3, 7, 5 } };
  std::vector<std::pair<std::string, Bytes>> seeds;

  ByteWriter raw = PositionalLight(0.5, 3.0, 0.25, 0.5);
  raw.U8(8);
  CubeCorners(raw);
  raw.U16(12);
  for (const auto& t : cube)
  {
    raw.U8(t[0]).U8(t[1]).U8(t[2]);
  }
  Receivers(raw);
  seeds.emplace_back("raw-cube-positional", raw.Bytes);

  // The same cube under a directional light, mirrored, weld tolerance 1e-3.
  ByteWriter sun;
  sun.U8(2 | (2 << 2)).U8(0);
  sun.Scalar(0.25).Scalar(1.0).Scalar(0.125).Scalar(0.05);
  sun.U8(8);
  CubeCorners(sun);
  sun.U16(12);
  for (const auto& t : cube)
  {
    sun.U8(t[0]).U8(t[1]).U8(t[2]);
  }
  Receivers(sun);
  seeds.emplace_back("raw-cube-directional-mirrored", sun.Bytes);

  // Light inside the cube, with out-of-range, NaN and duplicate-point triangles.
  ByteWriter inside = PositionalLight(0.1, 0.05, -0.1, 0.2);
  inside.U8(10);
  CubeCorners(inside);
  inside.U8(254).Special(penumbra::fuzz::TagNaN).Scalar(0).Scalar(0); // NaN point (index 8)
  inside.U8(134).U8(1).U8(0).U8(0xff); // (1,1,1) + 1e-9 jitter (index 9)
  inside.U16(16);
  for (const auto& t : cube)
  {
    inside.U8(t[0]).U8(t[1]).U8(t[2]);
  }
  inside.U8(0).U8(1).U8(248); // index 10: just past the end
  inside.U8(0).U8(252).U8(1); // 0xffffffff
  inside.U8(8).U8(1).U8(2);   // NaN corner
  inside.U8(9).U8(7).U8(6);   // welded onto corner 7: degenerate
  Receivers(inside);
  seeds.emplace_back("raw-inside-malformed", inside.Bytes);

  // vtkPolyData: a cube of quads, a strip, verts, lines, a pentagon with a repeated id and
  // empty, one- and two-point polygons.
  ByteWriter poly = PositionalLight(-2.0, 4.0, 1.0, 0.75);
  poly.Bytes[0] = 1;
  poly.U8(0).U8(9);
  CubeCorners(poly);
  poly.Lattice(0, 1, 0);
  static const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  poly.U8(13);
  for (const auto& q : quads)
  {
    poly.U8(2 | (4 << 2)).U8(q[0]).U8(q[1]).U8(q[2]).U8(q[3]);
  }
  poly.U8(3 | (5 << 2)).U8(0).U8(1).U8(8).U8(2).U8(3); // strip
  poly.U8(0 | (2 << 2)).U8(0).U8(8);                   // verts
  poly.U8(1 | (3 << 2)).U8(1).U8(2).U8(3);             // polyline
  poly.U8(2 | (5 << 2)).U8(4).U8(5).U8(8).U8(5).U8(6); // pentagon, repeated id
  poly.U8(2 | (0 << 2));                               // empty polygon
  poly.U8(2 | (1 << 2)).U8(3);                         // one point
  poly.U8(2 | (2 << 2)).U8(3).U8(4);                   // two points
  Receivers(poly);
  seeds.emplace_back("polydata-mixed-cells", poly.Bytes);

  // Regression: polygon and strip ids out of range (-1, n, >= 2^32 aliasing a valid id). Before
  // the fix vtkPolygon read past the points (ASan heap overflow) and 2^32 + i became point i.
  ByteWriter bad = PositionalLight(0.5, 3.0, 0.25, 0.5);
  bad.Bytes[0] = 1;
  bad.U8(0x20).U8(8); // float points
  CubeCorners(bad);
  bad.U8(5);
  bad.U8(2 | (4 << 2)).U8(0).U8(2).U8(251).U8(1);       // quad naming point n
  bad.U8(2 | (5 << 2)).U8(4).U8(5).U8(7).U8(250).U8(6); // pentagon with id -1
  bad.U8(3 | (4 << 2)).U8(0).U8(253).U8(1).U8(4).U8(5); // strip with 2^32 + 1
  bad.U8(2 | (3 << 2)).U8(253).U8(2).U8(1).U8(3);       // triangle with 2^32 + 2
  bad.U8(2 | (3 << 2)).U8(1).U8(3).U8(5);               // one valid triangle
  Receivers(bad);
  seeds.emplace_back("regression-polydata-invalid-ids", bad.Bytes);

  // Extreme values: 1e30 light, NaN radius, huge and tiny points.
  ByteWriter extreme;
  extreme.U8(4).U8(1); // weld tolerance 0
  extreme.Special(10).Special(10).Special(11).Special(13);
  extreme.U8(6);
  extreme.U8(254).Special(10).Scalar(0).Scalar(0);
  extreme.U8(254).Scalar(0).Special(10).Scalar(0);
  extreme.U8(254).Scalar(0).Scalar(0).Special(10);
  extreme.U8(254).Special(11).Scalar(0).Scalar(0);
  extreme.U8(254).Scalar(0).Special(11).Scalar(0);
  extreme.U8(254).Special(14).Scalar(0).Scalar(0);
  extreme.U16(4).U8(0).U8(1).U8(2).U8(3).U8(4).U8(0).U8(0).U8(1).U8(5).U8(2).U8(1).U8(0);
  Receivers(extreme);
  seeds.emplace_back("extreme-values", extreme.Bytes);

  // The receivers' boxes and the cuts of the cube's wedges to them: a ground, a box on it, an
  // invalid box, and a box one rounding step thick (its cell's centre rounds onto its face;
  // DisjointPieces lost it when it tested centres); the box kept from a frame before; two
  // half-spaces, nearly parallel (ClipBox's faces placed their crossings apart).
  ByteWriter cuts = raw;
  cuts.U8(4);
  cuts.U8(0).Point(-3.0, -3.0, -3.0).Point(3.0, -2.5, 3.0);
  cuts.U8(0).Point(-1.0, -2.5, -1.0).Point(1.0, -1.0, 1.0);
  cuts.U8(1).Point(0.0, 0.0, 0.0).Point(1.0, 1.0, 1.0);
  cuts.U8(0).RawPoint(2.0, 2.0, 2.0).RawPoint(3.0, std::nextafter(2.0, 3.0), 3.0);
  cuts.U8(0).Point(-3.5, -3.5, -3.5).Point(3.5, 3.5, 3.5);
  cuts.U8(2);
  cuts.Lattice(-1, -1, 1).Scalar(0.5);
  cuts.U8(254).Scalar(-1.0).Scalar(-1.0).Scalar(1.015625).Scalar(0.53125);
  seeds.emplace_back("receiver-boxes-and-cuts", cuts.Bytes);

  // Regression: a receivers' box 8 wide at 1e6 (kept from a frame before), cut by four planes of
  // a hard case's wedge. ClipBox's tolerance, 1e-12 of the box's size, was below the rounding of
  // its coordinates, and the cut came out open.
  ByteWriter far = raw;
  far.U8(1);
  far.U8(0).RawPoint(999996.2, 1000000.2, 999996.2).RawPoint(1000003.8, 1000001.396, 1000003.8);
  far.U8(0).RawPoint(999996, 1000000, 999996).RawPoint(1000004, 1000001.5961653268, 1000004);
  far.U8(4);
  far.RawPoint(-0.93509320259466078, 0.35440189398655975, 0).RawScalar(-580687.56823529059);
  far.RawPoint(0.72437288656730936, 0.6894083849259045, 0).RawScalar(1413784.1689847601);
  far.RawPoint(0, 0.76608032350236277, -0.64274484668685983).RawScalar(123338.0477948897);
  far.RawPoint(0, 0.13752506403373049, 0.99049828710731169).RawScalar(1128027.3131341906);
  seeds.emplace_back("regression-clip-far-from-origin", far.Bytes);
  return seeds;
}

} // namespace

void Usage(const char* program)
{
  std::fprintf(stderr,
    "usage: %s [--runs N] [--seed S] [--max-len L] [--crash-dir DIR] [--write-seeds DIR] "
    "[FILE|DIR]...\n"
    "  replays the corpus files given, then N pseudo-random and mutated inputs of at most L\n"
    "  bytes from seed S; --write-seeds writes the seed corpus into DIR and stops.\n",
    program);
}

int main(int argc, char* argv[])
{
  int runs = 0;
  int seed = 1;
  int maxLength = 4096;
  std::string seedDir;
  std::vector<fs::path> inputs;
  using namespace penumbra::bench;
  const std::vector<Option> table = { IntOption("--runs", 0, std::numeric_limits<int>::max(), runs),
    IntOption("--seed", 0, std::numeric_limits<int>::max(), seed),
    IntOption("--max-len", 0, 1 << 24, maxLength), TextOption("--crash-dir", CrashDir),
    TextOption("--write-seeds", seedDir) };
  if (!ParseOptions(
        argc, argv, table, Usage, [&](const char* input) { inputs.emplace_back(input); }))
  {
    return 2;
  }
  if (!seedDir.empty())
  {
    fs::create_directories(seedDir);
    for (const auto& s : Seeds())
    {
      const fs::path path = fs::path(seedDir) / s.first;
      WriteFile(path, s.second);
      std::printf("wrote %s (%zu bytes)\n", path.c_str(), s.second.size());
    }
    return 0;
  }

  CurrentPath = (fs::path(CrashDir) / "penumbra-fuzz-last-input").string();
  std::signal(SIGABRT, OnAbort);

  std::vector<fs::path> files;
  for (const fs::path& p : inputs)
  {
    if (!fs::exists(p))
    {
      std::fprintf(stderr, "no corpus at %s\n", p.string().c_str());
      return 2;
    }
    if (fs::is_directory(p))
    {
      for (const auto& entry : fs::directory_iterator(p))
      {
        if (entry.is_regular_file())
        {
          files.push_back(entry.path());
        }
      }
    }
    else
    {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end()); // directory order is not reproducible
  if (!inputs.empty() && files.empty())
  {
    std::fprintf(stderr, "the corpus given holds no file\n");
    return 2;
  }

  std::vector<Bytes> corpus;
  for (const fs::path& f : files)
  {
    corpus.push_back(ReadFile(f));
    Run(corpus.back(), f.string());
  }
  std::printf("replayed %zu corpus file(s)\n", corpus.size());

  std::mt19937 rng(seed);
  for (int r = 0; r < runs; ++r)
  {
    Bytes input;
    if (!corpus.empty() && r % 2 == 1)
    {
      input = Mutate(corpus[rng() % corpus.size()], corpus, rng, maxLength);
    }
    else
    {
      input.resize(rng() % (maxLength + 1));
      for (std::uint8_t& b : input)
      {
        b = static_cast<std::uint8_t>(rng());
      }
    }
    Run(input, "random input " + std::to_string(r));
  }
  std::printf("ran %d pseudo-random input(s) from seed %d: no invariant violated\n", runs, seed);
  return 0;
}

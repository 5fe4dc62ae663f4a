/**
 * @file penumbraFuzzInput.h
 * @brief The byte format penumbraGeometryFuzzer decodes, shared with the driver's seed writer.
 *
 * Every byte string is a valid input: a reader that runs out of bytes yields zeros, so a
 * truncated input is just a smaller scene. Layout (all integers little-endian):
 *
 *   u8 flags            bit 0: caster is a vtkPolyData (else raw points + triangles)
 *                       bit 1: mirrored; bits 2-3: weld tolerance (default, 0, 1e-3, 0.25)
 *   u8 lightKind        bit 0: positional (w = 1), else directional (w = 0)
 *   Scalar x, y, z, radius
 *   raw caster:         u8 pointCount, Point x pointCount, u16 triangleCount (mod 513),
 *                       RawIndex x 3 x triangleCount
 *   polydata caster:    u8 polyFlags (low nibble 15: null input; bit 4: no vtkPoints;
 *                       bit 5: float points), u8 pointCount, Point x pointCount, u8 cellCount,
 *                       per cell: u8 (bits 0-1: vert, line, poly, strip; bits 2-7 mod 17:
 *                       point count), CellId x count
 *   u8 receiverCount (mod 5), per receiver: u8 mode (bit 0: free Point, else on the far side
 *                       of each silhouette edge: u8 t along the edge, Scalar distance)
 *   u8 sampleCount (mod 17), Point target: SpreadLightSamples
 *   u8 boxCount (mod 11), Box x boxCount: the receivers' boxes; Box kept: the box kept from
 *                       the frame before (StableReceiverBox)
 *   u8 halfSpaceCount (mod 5), per half-space: Point normal, Scalar offset (ClipBox)
 *   camera:             Point eye, Point focal, u8 flags (mod 3: up y, z or x; bit 2:
 *                       parallel; bit 3: near 1000 times nearer), u8 near (1e-3 x (1 + near)),
 *                       u16 far (near x (1.5 + far)), u8 aspect (0.5 + aspect / 64), u8 view
 *                       angle (5 + angle % 160 degrees): culling, the tight depth range and the
 *                       occupancy grid (the first box its bounds, the others added)
 *   glyphs:             u8 flags (bit 0: scaling; bits 1-2 mod 3: scale mode; bit 3:
 *                       clamping; bits 4-5 mod 3: orientation mode), Scalar factor, Scalar
 *                       range x 2, Point scale tuple, Point position, Scalar orientation x 4,
 *                       u8 components (mod 4); imposters: Point centre, Point axis, Scalar
 *                       radius, Scalar length, Point actor translation
 *   plateaus:           u8 count (mod 9), Point x count (FitReceiverPlane), Point origin,
 *                       Point normal (the receiver plane of BuildPlateaus)
 *
 * Box: u8 mode (bit 0: invalid), Point, Point (the corners: their min and max).
 *
 * Scalar: u8 tag; tag % 16 in 0..9: int16 / 64; 10: 1e30; 11: 1e-30; 12: 0; 13: NaN; 14: Inf;
 * 15: 8 raw bytes. Bit 4 of the tag negates 10, 11, 12 and 14.
 * Point: u8 sel; < 128: a point of the 3x3x3 lattice {-1, 0, 1}^3 (collinear and coplanar
 * triples are frequent); < 192: the same plus int8 x 1e-9 per axis (welding); < 240: int8 / 32
 * per axis; < 255: three Scalars; 255: three raw doubles.
 */
#ifndef penumbraFuzzInput_h
#define penumbraFuzzInput_h

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace penumbra
{
namespace fuzz
{

enum ScalarTag : std::uint8_t
{
  TagHuge = 10,
  TagTiny = 11,
  TagZero = 12,
  TagNaN = 13,
  TagInf = 14,
  TagRaw = 15,
  TagNegative = 16
};

/// Reads the input front to back; past the end every read yields zero.
class ByteReader
{
public:
  ByteReader(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }

  std::uint8_t U8() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  std::uint16_t U16()
  {
    const std::uint16_t lo = this->U8();
    return static_cast<std::uint16_t>(lo | (this->U8() << 8));
  }
  std::uint32_t U32()
  {
    const std::uint32_t lo = this->U16();
    return lo | (std::uint32_t(this->U16()) << 16);
  }
  std::uint64_t U64()
  {
    const std::uint64_t lo = this->U32();
    return lo | (std::uint64_t(this->U32()) << 32);
  }
  double RawDouble()
  {
    const std::uint64_t bits = this->U64();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

/// Builds inputs in the same format (seed corpus).
class ByteWriter
{
public:
  std::vector<std::uint8_t> Bytes;

  /// A double's 8 bytes, as ByteReader::RawDouble reads them.
  ByteWriter& Raw(double value)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int byte = 0; byte < 8; ++byte)
    {
      this->U8(static_cast<unsigned>((bits >> (8 * byte)) & 0xff));
    }
    return *this;
  }

  ByteWriter& U8(unsigned value)
  {
    this->Bytes.push_back(static_cast<std::uint8_t>(value));
    return *this;
  }
  ByteWriter& U16(unsigned value) { return this->U8(value & 0xff).U8((value >> 8) & 0xff); }
  /// An ordinary scalar: the nearest multiple of 1/64.
  ByteWriter& Scalar(double value)
  {
    const auto q = static_cast<std::int16_t>(value * 64.0);
    return this->U8(0).U16(static_cast<std::uint16_t>(q));
  }
  ByteWriter& Special(std::uint8_t tag) { return this->U8(tag); }
  /// A lattice point, each coordinate in {-1, 0, 1}.
  ByteWriter& Lattice(int x, int y, int z)
  {
    return this->U8(static_cast<unsigned>((x + 1) + 3 * (y + 1) + 9 * (z + 1)));
  }
  /// A scalar of 8 raw bytes.
  ByteWriter& RawScalar(double value) { return this->U8(TagRaw).Raw(value); }
  /// A point of three raw doubles.
  ByteWriter& RawPoint(double x, double y, double z) { return this->U8(255).Raw(x).Raw(y).Raw(z); }
  /// An ordinary point, each coordinate a multiple of 1/32 in [-4, 4).
  ByteWriter& Point(double x, double y, double z)
  {
    this->U8(192);
    for (double c : { x, y, z })
    {
      this->U8(static_cast<std::uint8_t>(static_cast<std::int8_t>(c * 32.0)));
    }
    return *this;
  }
};

} // namespace fuzz
} // namespace penumbra

#endif

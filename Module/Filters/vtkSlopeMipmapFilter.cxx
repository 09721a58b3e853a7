#include "vtkSlopeMipmapFilter.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkReliefDepthImage.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkSlopeMipmapFilter);

namespace
{
constexpr int Components = 8;
constexpr int TopBits = 20;          // a node's top: a multiple of 2^-20, rounded down
constexpr int GrandchildCodes = 16;  // 4 bits a grandchild
constexpr int GrandchildExponents = 16; // 4 bits: steps 2^-4 to 2^-19
constexpr int ZeroCode = 512;        // the code of 0 (10 bits a bound); codes above are positive
constexpr double CodesPerOctave = 30.0;
constexpr double LeastOctave = -15.0; // magnitude code m stands for 2^(m / 30 - 15)

// The code of `value` rounded toward +infinity (`up`) or -infinity, by one more code than
// needed. 0 is exact.
unsigned int SlopeCode(double value, bool up)
{
  if (value == 0.0)
  {
    return ZeroCode;
  }
  if (!std::isfinite(value))
  {
    return up ? 2 * ZeroCode - 1 : 1; // the widest bound: NaN proves nothing
  }
  const double exact = (std::log2(std::abs(value)) - LeastOctave) * CodesPerOctave;
  // rounding up makes a positive value larger and a negative one smaller in magnitude
  const bool larger = (value > 0.0) == up;
  const int steps = larger ? static_cast<int>(std::ceil(exact)) + 1
                           : static_cast<int>(std::floor(exact)) - 1;
  // magnitudes below the least code become 0 or the least code; those beyond the largest
  // (2^2) its code: depths in [0, 1] give slopes of at most 1
  const int magnitude = std::min(std::max(steps, larger ? 1 : 0), ZeroCode - 1);
  return value > 0.0 ? ZeroCode + magnitude : ZeroCode - magnitude;
}

// The 20-bit code of a top, rounded down: the search may take a node to be no higher.
unsigned int TopCode(double top)
{
  if (!(top > 0.0))
  {
    return 0u; // also NaN (a precomputed image's): the highest top, which proves nothing
  }
  const double scaled = std::floor(std::ldexp(std::min(top, 1.0), TopBits));
  return static_cast<unsigned int>(std::min(scaled, std::ldexp(1.0, TopBits) - 1.0));
}

// The inverse of the step of grandchild codes on `exponent`, 2^(exponent + 4), and the
// step: both exact.
double GrandchildInverseStep(int exponent)
{
  return static_cast<double>(1 << (exponent + 4));
}

double GrandchildStep(int exponent)
{
  return 1.0 / GrandchildInverseStep(exponent);
}

// The 4-bit code of a grandchild whose top lies `offset` below its node's decoded top, on
// `step` (GrandchildStep; inverseStep its inverse): rounded down, and clamped to the largest
// code. The top and every code's offset are exact in a float, and so is their sum (at most
// 21 significant bits), but a GPU may take the step as a reciprocal a little too large: a
// code never reaches within a 1024th of a step of the grandchild's top. The step is a power
// of two, so `below` times its inverse is the exact quotient, and truncation (`below` > 0,
// clamped first) its floor.
unsigned int GrandchildCode(double offset, double step, double inverseStep)
{
  const double below = offset - step / 1024.0;
  return below > 0.0
    ? static_cast<unsigned int>(std::min(below * inverseStep, GrandchildCodes - 1.0))
    : 0u;
}

// Where code k of the output's three words lies (EncodeGrandchildTops): after the 4-bit
// exponent, codes 0 to 4 in the first word, 5 to 10 in the second, 11 to 15 in the third.
void GrandchildCodePlace(int k, int& word, int& shift)
{
  word = k < 5 ? 0 : (k < 11 ? 1 : 2);
  shift = k < 5 ? 4 + 4 * k : 4 * (k < 11 ? k - 5 : k - 11);
}

// The coded grandchildren of the output's three words: the exponent, then codes 0 to 15.
void UnpackGrandchildren(const double words[3], unsigned int& exponent, unsigned int codes[16])
{
  // a word out of range (a precomputed image's) codes every grandchild as the node's top
  unsigned int bits[3];
  for (int w = 0; w < 3; ++w)
  {
    bits[w] = words[w] >= 0.0 && words[w] < 16777216.0 ? static_cast<unsigned int>(words[w]) : 0u;
  }
  exponent = bits[0] & 15u;
  for (int k = 0; k < 16; ++k)
  {
    int word, shift;
    GrandchildCodePlace(k, word, shift);
    codes[k] = (bits[word] >> shift) & 15u;
  }
}
}

vtkSlopeMipmapFilter::vtkSlopeMipmapFilter() = default;

unsigned int vtkSlopeMipmapFilter::EncodeSlopes(double low, double high)
{
  return SlopeCode(low, false) + 1024u * SlopeCode(high, true);
}

double vtkSlopeMipmapFilter::DecodedTop(double top)
{
  return std::ldexp(static_cast<double>(TopCode(top)), -TopBits);
}

void vtkSlopeMipmapFilter::EncodeGrandchildTops(
  double top, const double grandchildTops[16], float words[3])
{
  const double base = DecodedTop(top);
  double offsets[16];
  for (int k = 0; k < 16; ++k)
  {
    offsets[k] = grandchildTops[k] - base;
  }
  // the step that rounds the sixteen tops down the least in all: a finer one holds the low
  // tops closer but clamps the high ones to the largest code
  int exponent = 0;
  double leastRounding = 0.0;
  for (int candidate = 0; candidate < GrandchildExponents; ++candidate)
  {
    const double step = GrandchildStep(candidate);
    const double inverseStep = GrandchildInverseStep(candidate);
    double rounding = 0.0;
    for (int k = 0; k < 16; ++k)
    {
      rounding += offsets[k] - GrandchildCode(offsets[k], step, inverseStep) * step;
    }
    if (candidate == 0 || rounding < leastRounding)
    {
      exponent = candidate;
      leastRounding = rounding;
    }
  }
  const double step = GrandchildStep(exponent);
  const double inverseStep = GrandchildInverseStep(exponent);
  unsigned int packed[3] = { static_cast<unsigned int>(exponent), 0u, 0u };
  for (int k = 0; k < 16; ++k)
  {
    int word, shift;
    GrandchildCodePlace(k, word, shift);
    packed[word] |= GrandchildCode(offsets[k], step, inverseStep) << shift;
  }
  for (int w = 0; w < 3; ++w)
  {
    words[w] = static_cast<float>(packed[w]); // at most 24 bits: exact
  }
}

void vtkSlopeMipmapFilter::PackNode(const double node[8], unsigned int texel[4])
{
  unsigned int exponent = 0;
  unsigned int codes[16];
  UnpackGrandchildren(node + 5, exponent, codes);
  texel[0] = TopCode(node[0]) | exponent << 20 | codes[14] << 24 | codes[15] << 28;
  texel[1] = EncodeSlopes(node[1], node[2]) | codes[8] << 20 | codes[9] << 24 | codes[10] << 28;
  texel[2] = EncodeSlopes(node[3], node[4]) | codes[11] << 20 | codes[12] << 24 | codes[13] << 28;
  texel[3] = 0u;
  for (int k = 0; k < 8; ++k)
  {
    texel[3] |= codes[k] << (4 * k);
  }
}

void vtkSlopeMipmapFilter::Compute(const vtkReliefDepthImage& field, vtkFloatArray* output)
{
  const int width = field.Width;
  const int height = field.Height;
  int atlas[2];
  GetAtlasSize(width, height, atlas);
  // texels outside every level: the deepest and flat, they never stop a ray
  for (int k = 0; k < Components; ++k)
  {
    output->FillComponent(k, k == 0 ? 1.0 : 0.0);
  }
  float* values = output->GetPointer(0);
  auto at = [&](int x, int y) {
    return values + (static_cast<size_t>(y) * atlas[0] + x) * Components;
  };

  // level 0: the patch's highest corner and the box of its gradient, extreme at corners
  this->ForRows(height, 8, 0.0, 0.8, [&](int begin, int end) {
    for (int j = begin; j < end; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        const float d00 = field.At(i, j);
        const float d10 = field.At(i + 1, j);
        const float d01 = field.At(i, j + 1);
        const float d11 = field.At(i + 1, j + 1);
        float* node = at(i, j);
        node[0] = std::min(std::min(d00, d10), std::min(d01, d11));
        node[1] = std::min(d10 - d00, d11 - d01);
        node[2] = std::max(d10 - d00, d11 - d01);
        node[3] = std::min(d01 - d00, d11 - d10);
        node[4] = std::max(d01 - d00, d11 - d10);
      }
    }
  });

  ReduceLevels(width, height, Components, values, [](float* node, const float* child, int) {
    node[0] = std::min(node[0], child[0]);
    node[1] = std::min(node[1], child[1]);
    node[2] = std::max(node[2], child[2]);
    node[3] = std::min(node[3], child[3]);
    node[4] = std::max(node[4], child[4]);
  });
  this->EncodeGrandchildren(width, height, values);
}

void vtkSlopeMipmapFilter::EncodeGrandchildren(int width, int height, float* values)
{
  int atlasSize[2];
  GetAtlasSize(width, height, atlasSize);
  const int top = GetTopLevel(width, height);
  for (int level = 1; level <= top; ++level)
  {
    int origin[2], size[2], below[2], belowSize[2];
    GetLevelPlacement(width, height, level, origin, size);
    // a level-1 node's slots hold its cells, each over two slots a side
    const int grandLevel = std::max(level - 2, 0);
    GetLevelPlacement(width, height, grandLevel, below, belowSize);
    auto texel = [&](const int place[2], int x, int y) {
      const size_t index = static_cast<size_t>(place[1] + y) * atlasSize[0] + place[0] + x;
      return values + index * Components;
    };
    // the grandchildren (a level-1 node's cells) of node `node` along one axis
    auto descendantRange = [&](int node, int axisSize, int& first, int& last) {
      int firstChild, lastChild;
      GetChildRange(node, axisSize, level, firstChild, lastChild);
      if (level == 1)
      {
        first = firstChild;
        last = lastChild;
        return;
      }
      int unused;
      GetChildRange(firstChild, axisSize, level - 1, first, unused);
      GetChildRange(lastChild, axisSize, level - 1, unused, last);
    };
    // the slots of descendant n of node `node` along one axis, as the search reads them:
    // a level-1 node's cell's min(2 (n - 2 node), 2) and the next; a grandchild's own,
    // min(n - 4 node, 3), and where its parent's two (reliefSlopeChildTop) miss it, as
    // when a single child has three children, also the nearer of those
    auto slotRange = [&](int n, int node, int axisSize, int& firstSlot, int& lastSlot) {
      if (level == 1)
      {
        firstSlot = std::min(2 * (n - 2 * node), 2);
        lastSlot = firstSlot + 1;
        return;
      }
      const int child = std::min(n / 2, GetLevelSize(axisSize, level - 1) - 1);
      const int childSlot = 2 * std::min(child - 2 * node, 1);
      const int own = std::min(n - 4 * node, 3);
      firstSlot = std::min(own, childSlot + 1);
      lastSlot = std::max(own, childSlot);
    };
    this->ForRows(size[1], 8, 0.8 + 0.2 * (level - 1) / top, 0.8 + 0.2 * level / top,
      [&](int begin, int end) {
        for (int j = begin; j < end; ++j)
        {
          int firstRow, lastRow;
          descendantRange(j, height, firstRow, lastRow);
          for (int i = 0; i < size[0]; ++i)
          {
            int firstColumn, lastColumn;
            descendantRange(i, width, firstColumn, lastColumn);
            float* node = texel(origin, i, j);
            // a slot no grandchild fills (an axis with a single child) holds the node's own
            // top, which proves nothing more
            double slotTops[16];
            std::fill(slotTops, slotTops + 16, 2.0);
            for (int y = firstRow; y <= lastRow; ++y)
            {
              int firstY, lastY;
              slotRange(y, j, height, firstY, lastY);
              for (int x = firstColumn; x <= lastColumn; ++x)
              {
                int firstX, lastX;
                slotRange(x, i, width, firstX, lastX);
                const double grandTop = texel(below, x, y)[0];
                for (int sy = firstY; sy <= lastY; ++sy)
                {
                  for (int sx = firstX; sx <= lastX; ++sx)
                  {
                    double& slot = slotTops[sx + 4 * sy];
                    slot = std::min(slot, grandTop);
                  }
                }
              }
            }
            for (double& slot : slotTops)
            {
              slot = slot > 1.5 ? node[0] : slot;
            }
            EncodeGrandchildTops(node[0], slotTops, node + 5);
          }
        }
      });
  }
}

void vtkSlopeMipmapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

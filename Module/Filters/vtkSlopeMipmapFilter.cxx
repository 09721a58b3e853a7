#include "vtkSlopeMipmapFilter.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkReliefDepthImage.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkSlopeMipmapFilter);

namespace
{
constexpr int Components = 6;
constexpr int ChildCodes = 32;     // 5 bits a child
constexpr int ChildExponents = 16; // 4 bits: steps 2^-4 to 2^-19
constexpr int ExponentUnit = 1 << 20;
constexpr int ZeroCode = 2048;      // the code of 0; codes above are positive
constexpr double CodesPerOctave = 128.0;
constexpr double LeastOctave = -15.0; // magnitude code m stands for 2^(m / 128 - 15)

// The code of `value` rounded toward +infinity (`up`) or -infinity, by one more code than
// needed. 0 is exact.
int SlopeCode(double value, bool up)
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
  // (2^0.99) its code: depths in [0, 1] give slopes of at most 1
  const int magnitude = std::min(std::max(steps, larger ? 1 : 0), ZeroCode - 1);
  return value > 0.0 ? ZeroCode + magnitude : ZeroCode - magnitude;
}
}

vtkSlopeMipmapFilter::vtkSlopeMipmapFilter() = default;

float vtkSlopeMipmapFilter::EncodeSlopes(double low, double high)
{
  return static_cast<float>(SlopeCode(low, false) * 4096 + SlopeCode(high, true));
}

float vtkSlopeMipmapFilter::EncodeChildTops(double top, const double childTops[4])
{
  double largest = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    largest = std::max(largest, childTops[k] - top);
  }
  int exponent = ChildExponents - 1;
  while (exponent > 0 && std::ldexp(ChildCodes - 1, -(exponent + 4)) < largest)
  {
    --exponent;
  }
  const double step = std::ldexp(1.0, -(exponent + 4));
  // the GPU adds the offset to the top in float and may round the step's division: a
  // code never reaches within 2^-20 + step / 1024 of the child's top
  const double margin = std::ldexp(1.0, -20) + step / 1024.0;
  int packed = exponent * ExponentUnit;
  for (int k = 0, weight = 1; k < 4; ++k, weight *= ChildCodes)
  {
    const double offset = childTops[k] - top - margin;
    const int code = offset > 0.0 ? std::min(static_cast<int>(offset / step), ChildCodes - 1) : 0;
    packed += code * weight;
  }
  return static_cast<float>(packed);
}

void vtkSlopeMipmapFilter::PackNode(const double node[6], float texel[4])
{
  texel[0] = static_cast<float>(node[0]);
  texel[1] = EncodeSlopes(node[1], node[2]);
  texel[2] = EncodeSlopes(node[3], node[4]);
  texel[3] = static_cast<float>(node[5]);
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

  // each node's children's tops by slot, gathered as its children are taken in, then
  // coded against the node's own (ReduceLevels visits nodes one at a time, in order)
  double childTops[4] = { 0.0, 0.0, 0.0, 0.0 };
  bool filled[4] = { false, false, false, false };
  ReduceLevels(
    width, height, Components, values,
    [&](float* node, const float* child, int slot) {
      node[0] = std::min(node[0], child[0]);
      node[1] = std::min(node[1], child[1]);
      node[2] = std::max(node[2], child[2]);
      node[3] = std::min(node[3], child[3]);
      node[4] = std::max(node[4], child[4]);
      childTops[slot] = filled[slot] ? std::min<double>(childTops[slot], child[0]) : child[0];
      filled[slot] = true;
    },
    [&](float* node) {
      // a slot no child fills (an axis with a single child) holds the node's own top,
      // which proves nothing more; the search asks for it only at such a node's far side
      for (int k = 0; k < 4; ++k)
      {
        childTops[k] = filled[k] ? childTops[k] : node[0];
        filled[k] = false;
      }
      node[5] = EncodeChildTops(node[0], childTops);
    });
}

void vtkSlopeMipmapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

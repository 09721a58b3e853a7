// The brute-force ground truth of a ray against the bilinear height field, in double
// precision: the unit tests' reference for every search, and the bench's (ReliefRobustStudy).
#ifndef ReliefReferenceHit_h
#define ReliefReferenceHit_h

#include "ReliefCpuMirror.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ReliefCpuMirror
{
// The first parameter where the ray meets the bilinear field, or 1 when it does not:
// every cell the ray crosses, found by listing all its centreline crossings, intersected
// analytically in double precision.
inline double ReferenceHit(const DepthField& field, const ReliefRay& ray)
{
  const double ox = double(ray.origin.x) * field.Width - 0.5;
  const double oy = double(ray.origin.y) * field.Height - 0.5;
  const double qx = double(ray.direction.x) * field.Width;
  const double qy = double(ray.direction.y) * field.Height;
  const double z0 = ray.origin.z;
  const double dz = ray.direction.z;
  std::vector<double> breaks = { 0.0, 1.0 };
  auto addCrossings = [&breaks](double origin, double run) {
    if (run == 0.0)
    {
      return;
    }
    const double end = origin + run;
    for (double line = std::ceil(std::min(origin, end)); line <= std::max(origin, end); line += 1.0)
    {
      const double t = (line - origin) / run;
      if (t > 0.0 && t < 1.0)
      {
        breaks.push_back(t);
      }
    }
  };
  addCrossings(ox, qx);
  addCrossings(oy, qy);
  std::sort(breaks.begin(), breaks.end());
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
  {
    const double ta = breaks[k];
    const double tb = breaks[k + 1];
    if (tb <= ta)
    {
      continue;
    }
    const double middle = 0.5 * (ta + tb);
    const int ci = static_cast<int>(std::floor(ox + middle * qx));
    const int cj = static_cast<int>(std::floor(oy + middle * qy));
    const double d00 = field.At(ci, cj);
    const double d10 = field.At(ci + 1, cj);
    const double d01 = field.At(ci, cj + 1);
    const double d11 = field.At(ci + 1, cj + 1);
    auto gap = [&](double t) {
      const double x = ox + t * qx - ci;
      const double y = oy + t * qy - cj;
      return d00 * (1 - x) * (1 - y) + d10 * x * (1 - y) + d01 * (1 - x) * y + d11 * x * y -
        (z0 + t * dz);
    };
    if (gap(ta) <= 0.0)
    {
      return ta;
    }
    // gap(t) = c0 + c1 t + c2 t^2 exactly; find its coefficients from three values
    const double g0 = gap(ta);
    const double g1 = gap(middle);
    const double g2 = gap(tb);
    const double h = middle - ta;
    const double c2 = (g2 - 2.0 * g1 + g0) / (2.0 * h * h);
    const double c1 = (g1 - g0) / h - c2 * h; // derivative at ta
    std::vector<double> roots;
    if (std::abs(c2) < 1e-300)
    {
      if (c1 < 0.0)
      {
        roots.push_back(-g0 / c1);
      }
    }
    else
    {
      const double discriminant = c1 * c1 - 4.0 * c2 * g0;
      if (discriminant >= 0.0)
      {
        const double root = std::sqrt(discriminant);
        const double q = -0.5 * (c1 + (c1 >= 0.0 ? root : -root));
        roots.push_back(q / c2);
        if (q != 0.0)
        {
          roots.push_back(g0 / q);
        }
      }
    }
    std::sort(roots.begin(), roots.end());
    for (double root : roots)
    {
      if (root >= 0.0 && root <= tb - ta)
      {
        return ta + root;
      }
    }
    if (g2 <= 0.0)
    {
      return tb;
    }
  }
  return 1.0;
}

// How far a hit lies from the reference: the larger of its texel and depth offsets.
inline double HitError(const DepthField& field, const ReliefRay& ray, double t, double reference)
{
  const double dt = std::abs(t - reference);
  const double texels = dt *
    std::max(std::abs(double(ray.direction.x) * field.Width),
      std::abs(double(ray.direction.y) * field.Height));
  return std::max(texels, dt * std::abs(double(ray.direction.z)));
}

}

#endif

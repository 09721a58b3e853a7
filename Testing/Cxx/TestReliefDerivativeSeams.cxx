// Texture tearing at creases (Tichenor's (2012) second limit), through ReliefDerivativeStudy: a
// sheet folded into flat panels, seen 45 degrees off its normal across the folds, with a
// ramp texture whose colour is the hit's texture coordinates. No baseline image: the
// same measure halfway between the folds, where the sheet is flat, is the reference.
// - Flat frames (the derivative frame without normals, the tangent frame with normals
//   split at the folds) are one and the same frame: their jumps agree, and at a 20-degree
//   crease they tear (measured: 10 levels against 1.5 between folds, depth 0.6 DepthScale).
// - The derivative frame with ComputeNormals, like the tangent frame with smooth
//   normals, does not: up to 45 degrees its jumps at the folds stay under 2.5 levels and
//   0.1 DepthScale (measured at most 2 and 0.054), within 1 level and 0.02 DepthScale of
//   the tangent frame's.
#include "ReliefDerivativeStudy.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>

int TestReliefDerivativeSeams(int, char*[])
{
  ReliefDerivativeStudy::Options options;
  options.Creases = { 0.0, 20.0, 45.0 };
  options.ViewAngles = {};
  std::map<std::pair<double, std::string>, ReliefDerivativeStudy::Seam> seams;
  for (const auto& seam : ReliefDerivativeStudy::MeasureSeams(options))
  {
    std::cout << "crease " << seam.Crease << ", " << seam.Frame << ": colour jump "
              << seam.ColourJump << " (between folds " << seam.FlatColourJump << "), depth jump "
              << seam.DepthJump << " (" << seam.FlatDepthJump << ")\n";
    seams[{ seam.Crease, seam.Frame }] = seam;
  }
  const auto& frames = ReliefDerivativeStudy::SeamFrames();
  const std::string& tangentSplit = frames[1];
  const std::string& computed = frames[2];
  const std::string& flat = frames[3];
  int failures = 0;
  auto check = [&](bool condition, const std::string& what) {
    if (!condition)
    {
      std::cerr << "ERROR: " << what << "\n";
      ++failures;
    }
  };
  const std::string& tangentSmooth = frames[0];
  for (double crease : options.Creases)
  {
    const auto& derivativeFlat = seams.at({ crease, flat });
    const auto& tangentFlat = seams.at({ crease, tangentSplit });
    check(std::abs(derivativeFlat.ColourJump - tangentFlat.ColourJump) <= 1.0 &&
        std::abs(derivativeFlat.DepthJump - tangentFlat.DepthJump) <= 0.05,
      "the derivative frame without normals is not the tangent frame's flat frame");
    const auto& smooth = seams.at({ crease, computed });
    const auto& tangent = seams.at({ crease, tangentSmooth });
    check(smooth.ColourJump <= 2.5 && smooth.DepthJump <= 0.1 &&
        smooth.ColourJump <= tangent.ColourJump + 1.0 &&
        smooth.DepthJump <= tangent.DepthJump + 0.02,
      "ComputeNormals leaves a seam at a " + std::to_string(crease) + "-degree crease");
  }
  const auto& torn = seams.at({ 20.0, flat });
  check(torn.ColourJump >= 3.0 * std::max(torn.FlatColourJump, 1.0) && torn.DepthJump > 0.3,
    "the flat frame no longer tears at a 20-degree crease: the measure has lost its seams");
  const auto& none = seams.at({ 0.0, flat });
  check(none.ColourJump <= 2.0 && none.DepthJump <= 0.05, "a seam where there is no crease");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

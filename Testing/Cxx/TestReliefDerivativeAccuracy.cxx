// The derivative frame against the ground truth and against the tangent frame (seed 003;
// the harness of vtkReliefDisplacementFilter), through ReliefDerivativeStudy: stones on
// a plane and on a torus, three views each. No baseline image: the truth and the
// tangent frame are the references.
// - On the plane both frames are the same affine mapping, computed two ways: their
//   renders may differ by float rounding only (no wrong pixel, colour RMSE under 0.002,
//   a tenth of an 8-bit level's worth of noise over the view).
// - On the torus the tangent frame interpolates per-vertex tangents and texture scales,
//   the derivative frame uses each triangle's exact mapping: they differ where the
//   interpolation does, but must stay closer to each other than half the tangent frame's
//   own distance to the truth, and the derivative frame no more than 0.03 further from
//   the truth than the tangent frame (measured: 0.009 to 0.014).
#include "ReliefDerivativeStudy.h"

#include <cstdlib>
#include <iostream>

int TestReliefDerivativeAccuracy(int, char*[])
{
  const ReliefDerivativeStudy::Options options; // untimed
  const std::vector<ReliefDerivativeStudy::Accuracy> rows =
    ReliefDerivativeStudy::MeasureAccuracy(options);
  int failures = 0;
  auto fail = [&](const ReliefDerivativeStudy::Accuracy& row, const std::string& what) {
    std::cerr << "ERROR: " << row.Shape << ", " << row.View << ": " << what << "\n";
    ++failures;
  };
  for (size_t r = 0; r + 1 < rows.size(); r += 2)
  {
    const auto& tangent = rows[r];
    const auto& derivative = rows[r + 1];
    std::cout << tangent.Shape << ", " << tangent.View << ": wrong pixels tangent "
              << tangent.WrongPixels << ", derivative " << derivative.WrongPixels
              << "; derivative against tangent: wrong " << derivative.WrongAgainstTangent
              << ", RMSE " << derivative.RmseAgainstTangent << "\n";
    if (tangent.Shape == "plane")
    {
      if (!(derivative.WrongAgainstTangent == 0.0 && derivative.RmseAgainstTangent < 0.002))
      {
        fail(derivative, "the derivative frame differs from the tangent frame on a plane");
      }
    }
    else if (!(derivative.WrongAgainstTangent < 0.5 * tangent.WrongPixels))
    {
      fail(derivative, "the frames are further apart than half the tangent frame's error");
    }
    if (!(derivative.WrongPixels <= tangent.WrongPixels + 0.03))
    {
      fail(derivative, "the derivative frame is further from the truth than the tangent frame");
    }
  }
  if (rows.size() != 12)
  {
    std::cerr << "ERROR: expected 2 shapes x 3 views x 2 frames, got " << rows.size() << "\n";
    ++failures;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

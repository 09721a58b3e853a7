// The derivative frame against the ground truth and against the tangent frame (Tichenor 2012;
// the harness of vtkReliefDisplacementFilter), through ReliefDerivativeStudy: stones on
// a plane and on a torus, three views each. No baseline image: the truth and the
// tangent frame are the references.
// - On the plane both frames are the same affine mapping, computed two ways: their
//   renders may differ by float rounding only: no pixel apart in depth, and a colour
//   RMSE under 1e-3 (a quarter of one 8-bit level; measured 4e-5 to 8e-4: a hit that
//   rounds to the other side of a texel centre turns the bilinear field's normal), with
//   every search method.
// - On the torus the tangent frame interpolates per-vertex tangents and texture scales,
//   the derivative frame uses each triangle's mapping against the interpolated normal:
//   they differ where the interpolation does, but must stay closer to each other than
//   half the tangent frame's own distance to the truth, and the derivative frame no
//   more than 0.03 further from the truth than the tangent frame (measured: 0.012 to
//   0.015).
#include "ReliefDerivativeStudy.h"
#include "ReliefScene.h"

#include <cstdlib>
#include <iostream>

namespace
{
int failures = 0;

void Fail(const ReliefDerivativeStudy::Accuracy& row, const std::string& what)
{
  std::cerr << "ERROR: " << row.Shape << ", " << row.View << ": " << what << "\n";
  ++failures;
}

// Checks the rows of one study: tangent, then derivative, per shape and view.
void Check(const std::vector<ReliefDerivativeStudy::Accuracy>& rows, size_t expected)
{
  if (rows.size() != expected)
  {
    std::cerr << "ERROR: expected " << expected << " rows, got " << rows.size() << "\n";
    ++failures;
    return;
  }
  const auto& frames = ReliefDerivativeStudy::Frames();
  for (size_t r = 0; r + 1 < rows.size(); r += 2)
  {
    const auto& tangent = rows[r];
    const auto& derivative = rows[r + 1];
    if (tangent.Frame != frames[0] || derivative.Frame != frames[1] ||
      tangent.View != derivative.View)
    {
      Fail(derivative, "rows out of order");
      continue;
    }
    std::cout << tangent.Shape << ", " << tangent.View << ": wrong pixels tangent "
              << tangent.WrongPixels << ", derivative " << derivative.WrongPixels
              << "; derivative against tangent: wrong " << derivative.WrongAgainstTangent
              << ", RMSE " << derivative.RmseAgainstTangent << "\n";
    if (tangent.Shape == "plane")
    {
      if (!(derivative.WrongAgainstTangent == 0.0 && derivative.RmseAgainstTangent < 1e-3))
      {
        Fail(derivative, "the derivative frame differs from the tangent frame on a plane");
      }
    }
    else if (!(derivative.WrongAgainstTangent < 0.5 * tangent.WrongPixels))
    {
      Fail(derivative, "the frames are further apart than half the tangent frame's error");
    }
    if (!(derivative.WrongPixels <= tangent.WrongPixels + 0.03))
    {
      Fail(derivative, "the derivative frame is further from the truth than the tangent frame");
    }
  }
}
}

int TestReliefDerivativeAccuracy(int, char*[])
{
  ReliefDerivativeStudy::Options options; // untimed, LinearBinary
  Check(ReliefDerivativeStudy::MeasureAccuracy(options), 2 * 3 * 2);
  // the frame serves every search: the other methods on the plane
  options.TorusToo = false;
  for (int method : ReliefScene::SearchMethods())
  {
    if (method != vtkOpenGLReliefMapper::LINEAR_BINARY)
    {
      std::cout << vtkOpenGLReliefMapper::GetSearchMethodAsString(method) << ":\n";
      options.SearchMethod = method;
      Check(ReliefDerivativeStudy::MeasureAccuracy(options), 3 * 2);
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

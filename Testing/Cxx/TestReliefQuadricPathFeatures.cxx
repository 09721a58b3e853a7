// vtkOpenGLQuadricPathFeatureMapper: round grooves around and along a coarse cylinder (48 x 8
// quads) on the tangent frame (left) and on the quadric frame (right). The baseline shows
// both; beside it the test measures the right outline of each half row by row: where a
// groove around the cylinder crosses it, the quadric frame's outline steps in (the ray comes
// back out of the quadric inside the groove: the paper's curved surfaces, s4.1), as deep as
// the groove within a few pixels, while the tangent frame's keeps the polygons' outline.
#include "ReliefPathScene.h"
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace
{
constexpr int Width = 800;
constexpr int Height = 400;

// Per row, the rightmost pixel of the half [first, last) that is not the background (the
// renderer's 0.1 0.12 0.16); -1 where the row is empty.
std::vector<int> RightOutline(const std::vector<unsigned char>& pixels, int first, int last)
{
  std::vector<int> outline(Height, -1);
  for (int y = 0; y < Height; ++y)
  {
    for (int x = first; x < last; ++x)
    {
      const unsigned char* rgb = &pixels[3 * (static_cast<size_t>(y) * Width + x)];
      if (std::abs(rgb[0] - 26) > 1 || std::abs(rgb[1] - 31) > 1 || std::abs(rgb[2] - 41) > 1)
      {
        outline[y] = x;
      }
    }
  }
  return outline;
}

// The outline's notches along the cylinder's side (the rows 20 or more from its ends, where
// the end's ellipse turns the outline): per row, how far it lies inside the farthest of the
// rows within 10 of it; the rows where that is 3 pixels or more, and the deepest.
struct Notches
{
  int Rows = 0;
  int Deepest = 0;
};

Notches NotchesOf(const std::vector<int>& outline)
{
  const auto covered = [](int x) { return x >= 0; };
  const int bottom = static_cast<int>(std::find_if(outline.begin(), outline.end(), covered) -
    outline.begin());
  const int top = static_cast<int>(outline.rend() - std::find_if(outline.rbegin(),
    outline.rend(), covered)) - 1;
  Notches notches;
  for (int y = bottom + 20; y <= top - 20; ++y)
  {
    const int farthest = *std::max_element(&outline[y - 10], &outline[y + 10] + 1);
    const int inside = farthest - outline[y];
    if (inside >= 3)
    {
      notches.Rows += 1;
      notches.Deepest = std::max(notches.Deepest, inside);
    }
  }
  return notches;
}
}

int TestReliefQuadricPathFeatures(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  // grooves 0.06 deep in the world on a cylinder of radius 0.4
  ReliefPathScene::ShowCurvedPathFeatures(window, Width, Height, 0.06);
  window->Render();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  const Notches flat = NotchesOf(RightOutline(pixels, 0, Width / 2));
  const Notches curved = NotchesOf(RightOutline(pixels, Width / 2, Width));
  std::cout << "notched rows of the right outline: tangent frame " << flat.Rows << " (deepest "
            << flat.Deepest << " px), quadric frame " << curved.Rows << " (deepest "
            << curved.Deepest << " px)\n";
  int failures = 0;
  if (flat.Rows != 0)
  {
    std::cerr << "The tangent frame's outline is notched: it should keep the polygons'.\n";
    ++failures;
  }
  // three grooves 9 pixels wide, notching the outline 4, 7 and 13 pixels deep as the view
  // looks down on them (19 pixels is the grooves' depth)
  if (curved.Rows < 10 || curved.Deepest < 8)
  {
    std::cerr << "The quadric frame's outline is not notched where the grooves cross it.\n";
    ++failures;
  }
  return (failures == 0 && vtkRegressionTestImage(window)) ? 0 : 1;
}

// ./relief demo: renders vtkRelief's built-in showcase into a folder and prints each
// image's median milliseconds per frame. Meshes come from VTK sources, height maps and
// colour textures from the project's Data/ folder: nothing is downloaded.
#include "ReliefPathScene.h"
#include "ReliefScene.h"

#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>

namespace
{
void WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}

void WriteWindow(vtkRenderWindow* window, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  capture->Update();
  WritePNG(capture->GetOutput(), path);
}

// The SampleCount image (red = samples, green = blue = 0) as a heat map: 0 samples
// blue, 20 and more red; the background turns black.
void WriteSampleCountHeatMap(vtkRenderWindow* window, const std::string& path)
{
  int* size = window->GetSize();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  vtkNew<vtkLookupTable> heat;
  heat->SetHueRange(0.667, 0.0);
  heat->SetTableRange(0.0, 20.0);
  heat->Build();
  vtkNew<vtkImageData> image;
  image->SetDimensions(size[0], size[1], 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i + 2 < pixels.size(); i += 3)
  {
    const bool covered = pixels[i + 1] == 0 && pixels[i + 2] == 0; // the background is blue-grey
    const unsigned char* color = covered ? heat->MapValue(pixels[i]) : nullptr;
    for (int c = 0; c < 3; ++c)
    {
      out[i + c] = covered ? color[c] : 0;
    }
  }
  WritePNG(image, path);
}

struct Showcase
{
  const char* Name;
  const char* Shows;
  std::function<void(vtkRenderWindow*)> Build;
};
}

int main(int argc, char* argv[])
{
  std::string output = "relief-demo";
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--data") && i + 1 < argc)
    {
      ReliefScene::SetDataDirectory(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--output") && i + 1 < argc)
    {
      output = argv[++i];
    }
    else
    {
      std::cerr << "usage: ReliefDemo [--data DIR] [--output DIR]\n";
      return 2;
    }
  }
  std::filesystem::create_directories(output);

  const std::vector<Showcase> showcase = {
    { "bricks_wall", "relief, self-occlusion, per-pixel light, self-shadows",
      [](vtkRenderWindow* w) { ReliefScene::ShowBricks(w, 640, 480, 45.0); } },
    { "plain_vs_relief", "the same bricks plainly textured (left) and relief mapped (right)",
      [](vtkRenderWindow* w) { ReliefScene::ShowPlainBesideRelief(w, 800, 400); } },
    { "stones_torus", "relief on a curved, coarse mesh",
      [](vtkRenderWindow* w) { ReliefScene::ShowTorus(w, 640, 480); } },
    { "quadric_silhouettes",
      "the flat frame (left) and the quadric frame (right) on a coarse torus",
      [](vtkRenderWindow* w) { ReliefScene::ShowQuadricSilhouettes(w, 800, 400); } },
    { "quadric_shadows",
      "shadow maps hold the relief: the flat frame's shadow (left), the quadric frame's (right)",
      [](vtkRenderWindow* w) { ReliefScene::ShowQuadricShadows(w, 800, 400); } },
    { "derivative_frames",
      "no tangents: torus.obj with its normals (left), without (middle), an icosahedron (right)",
      [](vtkRenderWindow* w) { ReliefScene::ShowDerivativeFrames(w, 960, 320); } },
    { "self_shadowing", "self-shadowing on (left) and off (right)",
      [](vtkRenderWindow* w) { ReliefScene::ShowSelfShadowing(w, 800, 400); } },
    { "interpenetration", "depth correction on (left) and off (right) with a plain sphere",
      [](vtkRenderWindow* w) { ReliefScene::ShowInterpenetration(w, 800, 400); } },
    { "search_methods",
      "thin features: Linear, LinearBinary, Secant, ExactDDA, SafetyRadius, ConeStep, "
      "MaximumMipmap, Automatic, RobustBinary, SlopeMipmap at 45 (top) and 80 degrees",
      [](vtkRenderWindow* w) { ReliefScene::ShowSearchMethods(w, 1600, 400); } },
    { "path_features",
      "vector detail (vtkOpenGLPathFeatureMapper): mortar joints meeting at ends, a crack "
      "narrowing to nothing, a weld bead cut by a dovetail slot, a ring of quadratic arcs",
      [](vtkRenderWindow* w) { ReliefPathScene::ShowPathFeatures(w, 640, 480, 50.0); } },
    { "path_features_closeup", "the same close up and low: the slot's overhang, the bead",
      [](vtkRenderWindow* w) { ReliefPathScene::ShowPathFeaturesCloseUp(w, 640, 480); } },
    { "path_features_on_relief",
      "features cut into a relief base: a saw cut and a crack through the bricks of a height "
      "map, a steel rod across them casting its shadow",
      [](vtkRenderWindow* w) { ReliefPathScene::ShowPathFeaturesOnRelief(w, 640, 480, 50.0); } },
    { "engraved_cylinder",
      "a label engraved with a V-bit on a cylinder of 48 x 8 quads (the quadric frame)",
      [](vtkRenderWindow* w) { ReliefPathScene::ShowEngravedCylinder(w, 640, 480); } },
    { "path_features_curved",
      "grooves on a coarse cylinder: the tangent frame (left) keeps the polygons' outline, the "
      "quadric frame (right) lets the grooves notch it",
      [](vtkRenderWindow* w) { ReliefPathScene::ShowCurvedPathFeatures(w, 800, 400, 0.06); } },
    { "impostor_beside_mesh",
      "an 18k-triangle mesh (left) and its relief impostor, six height fields in its box (right)",
      [](vtkRenderWindow* w) { ReliefScene::ShowImpostorBesideMesh(w, 800, 400); } },
    { "impostor_field", "400 impostors of that mesh sharing one mapper and its textures",
      [](vtkRenderWindow* w) { ReliefScene::ShowImpostorField(w, 800, 400, 400); } },
    { "sample_count",
      "height samples per pixel, Automatic (the default), the view ray's search (blue 0, red 20)",
      [](vtkRenderWindow* w) {
        auto mapper = ReliefScene::ShowBricks(w, 640, 480, 45.0);
        mapper->SetDisplayModeToSampleCount();
        mapper->FootprintShadingOff(); // the footprint's rays would multiply it by five
      } },
  };

  std::cout << "vtkRelief demo: images in " << std::filesystem::absolute(output).string() << "\n";
  for (const Showcase& scene : showcase)
  {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    scene.Build(window);
    const double milliseconds = ReliefScene::MedianFrameMilliseconds(window, 2, 10);
    const std::string path = output + "/" + scene.Name + ".png";
    if (std::string(scene.Name) == "sample_count")
    {
      WriteSampleCountHeatMap(window, path);
    }
    else
    {
      WriteWindow(window, path);
    }
    int* size = window->GetSize();
    std::printf("  %-23s %4dx%-4d %7.1f ms/frame  %s\n", (std::string(scene.Name) + ".png").c_str(),
      size[0], size[1], milliseconds, scene.Shows);
  }
  return 0;
}

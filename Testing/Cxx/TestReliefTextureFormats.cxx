// What the relief mapper keeps on the GPU and how it reads it back. GetTextureBytes()
// counts the 16-bit depth texture (full resolution only: every read is at level 0), a
// normal map's texture with its mipmaps only when the heights come with one
// (UseInputNormals), and the search method's acceleration image: two bytes a cell for
// ConeStep's cone map, floats for the others. The shading rebuilds normals from the depth
// texture, the bilinear field's own; given back as a normal map, the relief texture
// filter's per-texel normals (central differences) light the relief nearly alike, and
// tilted ones do not, so the normal map is what is read when there is one. No baseline
// image: renders are compared.
#include "ReliefChecks.h"
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkImageData.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace
{
constexpr int Width = 64;
constexpr int Height = 48;

// Texels of a width x height texture and all its mipmap levels, down to 1 x 1.
long MipmappedTexels(int width, int height)
{
  long texels = 0;
  for (int level = 0; (width >> level) > 0 || (height >> level) > 0; ++level)
  {
    texels += static_cast<long>(std::max(width >> level, 1)) * std::max(height >> level, 1);
  }
  return texels;
}

// Round bumps over the whole depth range, on a map that is not square.
vtkSmartPointer<vtkImageData> Bumps()
{
  return ReliefScene::HeightImage(Width, Height, [](int i, int j) {
    return static_cast<float>(std::sin(2.0 * M_PI * i / 16.0) * std::sin(2.0 * M_PI * j / 12.0));
  });
}

// Mean and largest difference of two renders' colour channels, in 8-bit levels.
struct Difference
{
  double Mean = 0.0;
  int Largest = 0;
};

Difference Compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  Difference difference;
  for (size_t k = 0; k < a.size(); ++k)
  {
    const int d = std::abs(int(a[k]) - int(b[k]));
    difference.Mean += d;
    difference.Largest = std::max(difference.Largest, d);
  }
  difference.Mean /= static_cast<double>(a.size());
  return difference;
}
}

int TestReliefTextureFormats(int, char*[])
{
  ReliefChecks check;

  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefScene::LitRenderer(window, 200, 150);
  vtkNew<vtkOpenGLReliefMapper> mapper;
  mapper->SetInputData(ReliefScene::Square(2.0));
  mapper->SetHeightMapData(Bumps());
  mapper->SetDepthScale(0.05);
  mapper->SetSelfShadowing(false);
  // each pixel lit by the normal at its hit: what is compared is how normals are read
  mapper->SetFootprintShading(false);
  mapper->SetSearchMethodToLinearBinary(); // the depth alone first
  renderer->AddActor(ReliefScene::ReliefActor(mapper, ""));
  ReliefScene::ViewSquare(renderer, 40.0);
  vtkNew<ReliefEventRecorder> messages;
  mapper->AddObserver(vtkCommand::ErrorEvent, messages);
  mapper->AddObserver(vtkCommand::WarningEvent, messages);

  // bytes: depth alone, then with each acceleration image
  check(mapper->GetTextureBytes() == 0, "no bytes before the first render");
  window->Render();
  const long depthBytes = 2L * Width * Height;
  std::cout << "LinearBinary: " << mapper->GetTextureBytes() << " bytes\n";
  check(mapper->GetTextureBytes() == depthBytes, "LinearBinary: the 16-bit depth");
  const std::vector<unsigned char> computedNormals = ReliefScene::Pixels(window);

  int atlas[2];
  vtkNew<vtkMaximumMipmapFilter> pyramid;
  pyramid->GetOutputSize(Width, Height, atlas);
  const struct
  {
    int Method;
    long Bytes;
  } accelerated[] = {
    { vtkOpenGLReliefMapper::CONE_STEP, 2L * Width * Height },
    { vtkOpenGLReliefMapper::SAFETY_RADIUS, 4L * Width * Height },
    { vtkOpenGLReliefMapper::MAXIMUM_MIPMAP, 4L * atlas[0] * atlas[1] },
    { vtkOpenGLReliefMapper::AUTOMATIC, 2L * Width * Height }, // the cone map
    { vtkOpenGLReliefMapper::ROBUST_BINARY, 4L * Width * Height }, // SafetyRadius's radii
    // top, two boxes, grandchildren's tops; without level 0, which the search reads from the
    // height map
    { vtkOpenGLReliefMapper::SLOPE_MIPMAP, 16L * (atlas[0] - Width) * atlas[1] },
  };
  for (const auto& method : accelerated)
  {
    mapper->SetSearchMethod(method.Method);
    window->Render();
    std::cout << mapper->GetSearchMethodAsString() << ": " << mapper->GetTextureBytes()
              << " bytes\n";
    check(mapper->GetTextureBytes() == depthBytes + method.Bytes,
      std::string(mapper->GetSearchMethodAsString()) + ": depth and acceleration image");
  }
  mapper->SetSearchMethod(vtkOpenGLReliefMapper::LINEAR_BINARY);
  window->Render();
  check(mapper->GetTextureBytes() == depthBytes, "an unused acceleration image is not counted");

  // the filter's own normals, given back as a normal map with the depth in alpha
  vtkReliefTextureFilter* reliefTexture = mapper->GetReliefTextureFilter();
  reliefTexture->Update();
  vtkNew<vtkImageData> normalMap;
  normalMap->DeepCopy(reliefTexture->GetOutput());
  mapper->SetHeightMapData(normalMap);
  reliefTexture->SetInputConventionToDepth();
  reliefTexture->UseInputNormalsOn();
  window->Render();
  std::cout << "with a normal map: " << mapper->GetTextureBytes() << " bytes\n";
  check(mapper->GetTextureBytes() == depthBytes + 4 * MipmappedTexels(Width, Height),
    "a normal map adds its (nx, ny) in 16 bits, mipmapped");
  const Difference alike = Compare(computedNormals, ReliefScene::Pixels(window));
  std::cout << "computed normals against the same normals as a map: mean " << alike.Mean
            << ", largest " << alike.Largest << " levels\n";
  // The same relief lit two ways: bilinear blends of the filter's per-texel normals
  // (central differences over two texels) against the gradient of the bilinear field
  // itself, which turns at texel centres: 3 levels on average here, up to a hundred on a
  // few pixels where the bumps turn fastest; other normals differ by tens of levels on
  // average (below).
  check(alike.Mean < 5.0, "a normal map of the computed normals looks alike");

  // every normal tilted 37 degrees toward +x: the lighting follows the map
  auto* texels = static_cast<float*>(normalMap->GetScalarPointer());
  for (vtkIdType texel = 0; texel < normalMap->GetNumberOfPoints(); ++texel)
  {
    texels[4 * texel + 0] = 0.6f;
    texels[4 * texel + 1] = 0.0f;
    texels[4 * texel + 2] = 0.8f;
  }
  normalMap->Modified();
  window->Render();
  const Difference tilted = Compare(computedNormals, ReliefScene::Pixels(window));
  std::cout << "tilted normal map: mean " << tilted.Mean << " levels\n";
  check(tilted.Mean > 10.0, "the normal map lights the relief");

  // back to computed normals: the normal map's texture goes
  reliefTexture->UseInputNormalsOff();
  window->Render();
  check(mapper->GetTextureBytes() == depthBytes, "computed normals need no normal texture");

  mapper->ReleaseGraphicsResources(window);
  check(mapper->GetTextureBytes() == 0, "no bytes after ReleaseGraphicsResources");
  check(messages->Events.empty(), "silent throughout");
  return check.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
}

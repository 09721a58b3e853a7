// Each mapper compiles its own frame and no other: the fragment shader of the tangent,
// quadric (both distance modes) and derivative (with and without vertex normals)
// mappers holds its frame's file and none of the others', the frame's defines come
// before the code they select, and a mapper binds and builds nothing of a frame it does
// not use. The exact distance mode changes what the quadric mapper draws. No baseline.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkShader.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// A relief mapper keeping the shader sources it built, and telling whether it made a
// tangent frame filter.
template <typename Mapper>
class Capturing : public Mapper
{
public:
  vtkTypeMacro(Capturing, Mapper);
  static Capturing* New()
  {
    auto* mapper = new Capturing;
    mapper->InitializeObjectBase();
    return mapper;
  }
  std::string Vertex;
  std::string Fragment;
  bool MadeTangentFrame() const { return this->TangentFrame != nullptr; }

protected:
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override
  {
    this->Mapper::ReplaceShaderValues(shaders, ren, actor);
    this->Vertex = shaders[vtkShader::Vertex]->GetSource();
    this->Fragment = shaders[vtkShader::Fragment]->GetSource();
  }
};

int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "ERROR: " << what << "\n";
    ++Failures;
  }
}

bool Has(const std::string& source, const char* text)
{
  return source.find(text) != std::string::npos;
}

// `first` occurs, and before `second`.
bool Before(const std::string& source, const char* first, const char* second)
{
  const auto at = source.find(first);
  return at != std::string::npos && at < source.find(second);
}

// Renders `mapper` on `mesh` with the bricks' heights; the window's pixels.
std::vector<unsigned char> Render(vtkRenderWindow* window, vtkOpenGLReliefMapper* mapper,
  vtkPolyData* mesh)
{
  window->GetRenderers()->RemoveAllItems();
  auto renderer = ReliefScene::LitRenderer(window, 120, 120);
  mapper->SetInputData(mesh);
  mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  mapper->SetDepthScale(0.08);
  renderer->AddActor(ReliefScene::ReliefActor(mapper, ""));
  renderer->ResetCamera();
  window->Render();
  return ReliefScene::Pixels(window);
}

const char* const TangentFrame = "ReliefFrame reliefTangentFrame(";
const char* const QuadricFrame = "ReliefFrame reliefQuadricFrame(";
const char* const DerivativeFrame = "ReliefFrame reliefDerivativeFrame(";
const char* const TangentBasis = "ReliefTangentBasis reliefTangentBasis(";
}

int TestReliefFrameSources(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  auto sphere = ReliefScene::Sphere(24);

  vtkNew<Capturing<vtkOpenGLReliefMapper>> tangent;
  Render(window, tangent, sphere);
  Check(Has(tangent->Fragment, TangentFrame) && Has(tangent->Fragment, TangentBasis),
    "the tangent mapper compiles the tangent frame");
  Check(!Has(tangent->Fragment, QuadricFrame) && !Has(tangent->Fragment, DerivativeFrame),
    "the tangent mapper compiles no other frame");

  vtkNew<Capturing<vtkOpenGLQuadricReliefMapper>> approximate;
  const auto approximatePixels = Render(window, approximate, sphere);
  Check(Has(approximate->Fragment, QuadricFrame) && Has(approximate->Fragment, TangentBasis),
    "the quadric mapper compiles the quadric frame over the tangent basis");
  Check(!Has(approximate->Fragment, TangentFrame) && !Has(approximate->Fragment, DerivativeFrame),
    "the quadric mapper compiles no other frame");
  Check(!Has(approximate->Fragment, "#define RELIEF_EXACT_DISTANCE"),
    "the approximate distance compiles without the exact one");

  vtkNew<Capturing<vtkOpenGLQuadricReliefMapper>> exact;
  exact->SetDistanceModeToExact();
  const auto exactPixels = Render(window, exact, sphere);
  Check(Before(exact->Fragment, "#define RELIEF_EXACT_DISTANCE", "vec3 reliefRayAt("),
    "the exact distance is defined before the ray code it selects");
  int differing = 0;
  for (size_t i = 0; i < exactPixels.size(); ++i)
  {
    differing += exactPixels[i] != approximatePixels[i] ? 1 : 0;
  }
  std::cout << "exact against approximate distance: " << differing << " values differ\n";
  Check(differing > 0, "the exact distance changes what the quadric mapper draws");

  // the derivative frame on a mesh without normals, then with them
  vtkNew<vtkPolyData> bare;
  bare->DeepCopy(sphere);
  bare->GetPointData()->SetNormals(nullptr);
  vtkNew<Capturing<vtkOpenGLDerivativeReliefMapper>> derivative;
  Render(window, derivative, bare);
  Check(Has(derivative->Fragment, DerivativeFrame), "the derivative mapper compiles its frame");
  Check(!Has(derivative->Fragment, TangentBasis) && !Has(derivative->Fragment, QuadricFrame),
    "the derivative mapper compiles no tangent basis and no other frame");
  Check(!Has(derivative->Vertex, "reliefTangentMC") &&
      !Has(derivative->Vertex, "#define RELIEF_VERTEX_NORMALS"),
    "without normals the derivative mapper's vertex shader reads no frame attribute");
  Check(!derivative->MadeTangentFrame(), "the derivative mapper makes no tangent frame filter");
  vtkNew<Capturing<vtkOpenGLDerivativeReliefMapper>> smooth;
  Render(window, smooth, sphere);
  Check(Before(smooth->Fragment, "#define RELIEF_VERTEX_NORMALS", DerivativeFrame) &&
      Before(smooth->Vertex, "#define RELIEF_VERTEX_NORMALS", "in vec3 reliefNormalMC;") &&
      !Has(smooth->Vertex, "reliefTangentMC"),
    "with normals the derivative frame reads them, and no tangents");
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

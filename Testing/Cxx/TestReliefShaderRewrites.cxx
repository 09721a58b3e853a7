// vtkReliefShaderRewrites against the shader code of the VTK the project is built with:
// VTK's stock mapper renders the configurations the relief mappers meet (unlit, a
// headlight, directional lights, positional lights, an actor texture, edges through a
// geometry shader), and in what it generates every tag the relief's code goes at must
// exist, every light's diffuse term must be found, and the texture reads and texture
// coordinates must be where the rewrites look. A VTK whose templates or lighting code
// moved fails here, by name, before any picture could. No baseline image.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkImageData.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefShaderRewrites.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkShader.h"
#include "vtkTexture.h"

#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

namespace
{
// VTK's stock mapper, keeping each stage's template (before VTK fills its tags) and
// generated code (after).
class CapturingMapper : public vtkOpenGLPolyDataMapper
{
public:
  static CapturingMapper* New();
  vtkTypeMacro(CapturingMapper, vtkOpenGLPolyDataMapper);
  std::map<vtkShader::Type, std::string> Templates;
  std::map<vtkShader::Type, std::string> Generated;

protected:
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override
  {
    for (const auto& stage : shaders)
    {
      this->Templates[stage.first] = stage.second->GetSource();
    }
    this->Superclass::ReplaceShaderValues(shaders, ren, actor);
    for (const auto& stage : shaders)
    {
      this->Generated[stage.first] = stage.second->GetSource();
    }
  }
};
vtkStandardNewMacro(CapturingMapper);

int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "ERROR: " << what << "\n";
    ++Failures;
  }
}

struct Configuration
{
  const char* Name;
  int Lights;     // 0: the headlight; else directional or positional lights
  bool Positional;
  bool Lit;
  bool Textured;
  bool Edges;
};

CapturingMapper* RenderWith(vtkRenderWindow* window, const Configuration& configuration)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  for (int k = 0; k < configuration.Lights; ++k)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(1.0 + k, 1.0, 2.0);
    light->SetPositional(configuration.Positional);
    renderer->AddLight(light);
  }
  auto* mapper = CapturingMapper::New();
  mapper->SetInputData(ReliefScene::Square(1.0));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  mapper->Delete(); // the actor holds it
  actor->GetProperty()->SetLighting(configuration.Lit);
  actor->GetProperty()->SetEdgeVisibility(configuration.Edges);
  if (configuration.Textured)
  {
    vtkNew<vtkTexture> texture;
    texture->SetInputData(ReliefScene::ReadImage("bricks_color.png"));
    actor->SetTexture(texture);
  }
  renderer->AddActor(actor);
  renderer->ResetCamera();
  window->Render();
  return mapper;
}
}

int TestReliefShaderRewrites(int, char*[])
{
  using Rewrites = vtkReliefShaderRewrites;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(64, 64);
  const Configuration configurations[] = {
    { "unlit", 0, false, false, true, false },
    { "headlight", 0, false, true, true, false },
    { "two directional lights", 2, false, true, true, false },
    { "two positional lights", 2, true, true, false, false },
    { "edges", 0, false, true, false, true },
  };
  for (const Configuration& configuration : configurations)
  {
    CapturingMapper* mapper = RenderWith(window, configuration);
    const std::string name = configuration.Name;
    for (const Rewrites::Tag& tag : Rewrites::GetTags())
    {
      const bool geometry = tag.Stage == vtkShader::Geometry;
      // the normal's code only where lit; the geometry stage only with edges
      if ((geometry && !configuration.Edges) ||
        (tag.Name == Rewrites::FragmentNormal && !configuration.Lit))
      {
        continue;
      }
      std::string source = mapper->Templates[tag.Stage];
      Check(Rewrites::InsertAfter(source, tag.Name, "// relief"),
        name + ": VTK's template has no " + tag.Name);
    }
    std::string fragment = mapper->Generated[vtkShader::Fragment];
    const int weighted = Rewrites::LightThrough(fragment, "reliefDiffuse", "reliefShadow");
    if (configuration.Lit)
    {
      // VTK writes each light's lighting out: one term per light, the headlight's too
      const int expected = std::max(configuration.Lights, 1);
      Check(weighted == expected,
        name + ": " + std::to_string(weighted) + " diffuse terms found, not " +
          std::to_string(expected));
      Check(fragment.find("normalVCVSOutput, -") == std::string::npos &&
          fragment.find("max(0.0,normalVCVSOutput.z)") == std::string::npos,
        name + ": a diffuse cosine left as VTK wrote it");
    }
    if (configuration.Textured)
    {
      Check(fragment.find(Rewrites::GetTextureCoordinates()) != std::string::npos,
        name + ": the fragment shader does not read " + Rewrites::GetTextureCoordinates());
      Check(Rewrites::ReadTexturesThrough(fragment, "reliefTextureAtRay", "reliefColourAtRay") >= 1,
        name + ": no texture read at the texture coordinates found");
    }
    // the model-to-view matrix is declared once whatever VTK did
    std::string vertex = mapper->Generated[vtkShader::Vertex] + "\n//VTK::Relief::CameraDec";
    Rewrites::DeclareModelToView(vertex, "//VTK::Relief::CameraDec");
    const auto first = vertex.find("uniform mat4 MCVCMatrix;");
    Check(first != std::string::npos &&
        vertex.find("uniform mat4 MCVCMatrix;", first + 1) == std::string::npos,
      name + ": MCVCMatrix is not declared exactly once");
  }

  // colour textures are read through the colour read, the physically based property's
  // normal, material, anisotropy and emissive textures through the plain one
  const std::string at = Rewrites::GetTextureCoordinates();
  std::string reads = "a = texture(texture_0, " + at + "); b = texture(albedoTex, " + at +
    "); c = texture(normalTex, " + at + "); d = texture(materialTex, " + at + ");";
  Check(Rewrites::ReadTexturesThrough(reads, "plain", "colour") == 4 &&
      reads == "a = colour(texture_0, " + at + "); b = colour(albedoTex, " + at +
        "); c = plain(normalTex, " + at + "); d = plain(materialTex, " + at + ");",
    "colour and other textures read apart: " + reads);

  // the rewrites say so where the code holds nothing they look for, and change nothing
  std::string other = "void main() { df = max(0.0, dot(n, l)); }";
  const std::string unchanged = other;
  Check(!Rewrites::InsertAfter(other, Rewrites::FragmentStart, "x") &&
      !Rewrites::InsertBefore(other, Rewrites::FragmentStart, "x") &&
      !Rewrites::Replace(other, Rewrites::FragmentDepth, "x") &&
      Rewrites::LightThrough(other, "reliefDiffuse", "reliefShadow") == 0 &&
      Rewrites::ReadTexturesThrough(other, "reliefTextureAtRay", "reliefColourAtRay") == 0 && other == unchanged,
    "rewrites of code without their tags or statements");
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

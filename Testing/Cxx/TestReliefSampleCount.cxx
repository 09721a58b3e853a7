// SampleCount display mode, the measure of cost: every covered pixel reports the height
// samples its view ray took, within the bounds of the search method, and with footprint
// shading those of the rays through four points of the pixel too; switching the
// method or footprint shading rebuilds the shader, uniform-only setters modify the
// mapper and rebuild neither its shader nor its buffers, and released graphics
// resources come back.
#include "ReliefChecks.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

namespace
{
// The relief mapper, counting its shader and buffer builds.
class CountingMapper : public vtkOpenGLReliefMapper
{
public:
  static CountingMapper* New();
  vtkTypeMacro(CountingMapper, vtkOpenGLReliefMapper);
  int ShaderBuilds = 0;
  int BufferBuilds = 0;

protected:
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override
  {
    ++this->ShaderBuilds;
    this->Superclass::ReplaceShaderValues(shaders, ren, actor);
  }
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* actor) override
  {
    ++this->BufferBuilds;
    this->Superclass::BuildBufferObjects(ren, actor);
  }
};
vtkStandardNewMacro(CountingMapper);

struct Counts
{
  int Pixels = 0;
  int Minimum = 256;
  int Maximum = 0;
  double Mean = 0.0;
};

Counts SampleCounts(vtkRenderWindow* window)
{
  window->Render();
  Counts counts;
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  double sum = 0.0;
  for (size_t i = 0; i + 2 < pixels.size(); i += 3)
  {
    if (pixels[i + 2] > 0 || pixels[i + 1] > 0)
    {
      continue; // background
    }
    ++counts.Pixels;
    sum += pixels[i];
    counts.Minimum = std::min<int>(counts.Minimum, pixels[i]);
    counts.Maximum = std::max<int>(counts.Maximum, pixels[i]);
  }
  counts.Mean = counts.Pixels ? sum / counts.Pixels : 0.0;
  std::cout << "samples per pixel: " << counts.Minimum << " to " << counts.Maximum << ", mean "
            << counts.Mean << " over " << counts.Pixels << " pixels\n";
  return counts;
}
}

int TestReliefSampleCount(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefScene::LitRenderer(window, 200, 150);
  renderer->SetBackground(0.0, 0.0, 1.0);
  vtkNew<CountingMapper> mapper;
  mapper->SetInputData(ReliefScene::Square(2.0));
  mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  mapper->SetDepthScale(0.05);
  mapper->SetDisplayModeToSampleCount();
  mapper->FootprintShadingOff(); // first the view ray's own search
  renderer->AddActor(ReliefScene::ReliefActor(mapper, "bricks_color.png"));
  ReliefScene::ViewSquare(renderer, 45.0);
  ReliefChecks check;

  // the default, Automatic: rays 50 texels long, about 10 pixels on screen, stepped over
  // the cone map; with a tolerance wider than that, no search: a secant step, 3 samples
  Counts automatic = SampleCounts(window);
  check(automatic.Pixels > 5000 && automatic.Minimum >= 1 && automatic.Maximum < 255,
    "Automatic covers the view and ends");
  const int automaticShaderBuilds = mapper->ShaderBuilds;
  mapper->SetScreenTolerance(100.0);
  Counts coarse = SampleCounts(window);
  check(coarse.Pixels == automatic.Pixels && coarse.Maximum <= 3 && coarse.Mean < automatic.Mean,
    "a tolerance wider than the relief on screen takes at most 3 samples");
  check(mapper->ShaderBuilds == automaticShaderBuilds, "the tolerance is a uniform");
  mapper->SetScreenTolerance(0.5);

  // LinearBinary 10 + 5: the linear search stops at its first hit (1 to 10 samples;
  // at least 2 here since no texel is at depth 0.1 or less), then bisects 5 times.
  mapper->SetSearchMethodToLinearBinary();
  Counts linearBinary = SampleCounts(window);
  check(linearBinary.Pixels > 5000, "the square covers the view");
  check(linearBinary.Minimum >= 6 && linearBinary.Maximum <= 15, "LinearBinary takes 6 to 15");
  check(automatic.Mean < linearBinary.Mean, "Automatic, exact here, takes fewer samples");

  // the footprint's four rays, searched alike where a pixel spans 0.7 texels or more (the
  // bricks' 512 texels on 2 tiles seen at 45 degrees: everywhere) and counted
  mapper->FootprintShadingOn();
  Counts footprint = SampleCounts(window);
  check(footprint.Minimum >= 5 * 6 && footprint.Maximum <= 5 * 15,
    "footprint shading: five LinearBinary searches a pixel");
  // compiled in or out (on llvmpipe a uniform that turned it off would still cost a pass)
  const int footprintBuilds = mapper->ShaderBuilds;
  mapper->FootprintShadingOff();
  Counts plain = SampleCounts(window);
  check(mapper->ShaderBuilds > footprintBuilds, "footprint shading off rebuilds the shader");
  check(plain.Minimum >= 6 && plain.Maximum <= 15, "and one search a pixel is left");

  const vtkMTimeType before = mapper->GetMTime();
  const int shaderBuilds = mapper->ShaderBuilds;
  const int bufferBuilds = mapper->BufferBuilds;
  mapper->SetDepthScale(0.02);
  mapper->SetLinearSteps(20);
  mapper->SetBinarySteps(3);
  mapper->SetSelfShadowing(false);
  mapper->SetDepthCorrection(false);
  mapper->SetTwoSidedRelief(true);
  mapper->SetFootprintShading(true);
  mapper->SetFootprintShading(false);
  check(mapper->GetMTime() > before, "setters modify the mapper");
  Counts moreSteps = SampleCounts(window);
  check(shaderBuilds > 0 && mapper->ShaderBuilds == shaderBuilds,
    "uniform-only setters, and footprint shading on and back off, do not rebuild the shader");
  check(bufferBuilds > 0 && mapper->BufferBuilds == bufferBuilds,
    "uniform-only setters do not rebuild the buffers");
  check(moreSteps.Minimum >= 4 && moreSteps.Maximum <= 23, "LinearBinary 20 + 3 takes 4 to 23");
  check(moreSteps.Maximum > 15, "the new step counts reach the shader");

  mapper->SetTwoSidedRelief(false);
  const vtkMTimeType beforeMethod = mapper->GetMTime();
  mapper->SetSearchMethodToLinear();
  check(mapper->GetMTime() > beforeMethod, "the search method modifies the mapper");
  mapper->SetLinearSteps(10);
  Counts linear = SampleCounts(window);
  check(mapper->ShaderBuilds > shaderBuilds, "a new search method rebuilds the shader");
  check(mapper->BufferBuilds == bufferBuilds, "and not the buffers");
  check(linear.Minimum >= 1 && linear.Maximum <= 10, "Linear takes 1 to 10");

  mapper->SetSearchMethodToLinearBinary();
  mapper->SetBinarySteps(5);
  mapper->SetDepthScale(0.05);
  Counts again = SampleCounts(window);
  check(again.Mean == linearBinary.Mean, "switching back gives the same cost");

  // released graphics resources (a context change) are rebuilt on the next render
  renderer->ReleaseGraphicsResources(window);
  Counts rebuilt = SampleCounts(window);
  check(rebuilt.Mean == linearBinary.Mean, "textures and shaders come back after release");
  return check.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
}

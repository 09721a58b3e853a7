// Brute-force ground truth for the searches of the CPU mirror, and the height fields
// and rays they are proven on: shared by the search tests of every method.
#ifndef ReliefSearchReference_h
#define ReliefSearchReference_h

#include "ReliefMirrorMaps.h"
#include "ReliefReferenceHit.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkOpenImageIOReader.h"
#include "vtkPointData.h"
#include "vtkReliefTextureFilter.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

// one copy per test source, like the mirror's shader code it uses
namespace
{
using namespace ReliefCpuMirror;

constexpr int RayCount = 10000;
constexpr double Pi = 3.14159265358979323846;
constexpr double Tolerance = 1e-3; // texels and depth

// A depth field as the pipeline gives it to the mapper, and its pyramid from
// vtkMaximumMipmapFilter.
struct Scene
{
  std::string Name;
  DepthField Field;
  DepthPyramid Pyramid;
};

Scene MakeScene(const std::string& name, const DepthField& field)
{
  return Scene{ name, field, PyramidOf(field) };
}

DepthField RandomField(int width, int height, unsigned seed, float low, float high)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<float> depth(low, high);
  DepthField field;
  field.Width = width;
  field.Height = height;
  for (int k = 0; k < width * height; ++k)
  {
    field.Depths.push_back(depth(generator));
  }
  return field;
}

// A height map of Data/ as the relief texture filter turns it into depths; resampled to
// size x size first where size is given, as the bench's methods table does.
DepthField DataField(const char* file, int size = 0)
{
  const char* data = std::getenv("RELIEF_DATA_DIR");
  vtkNew<vtkOpenImageIOReader> reader;
  reader->SetFileName((std::string(data ? data : "Data") + "/" + file).c_str());
  vtkSmartPointer<vtkAlgorithm> heights = reader.GetPointer();
  if (size > 0)
  {
    auto resize = vtkSmartPointer<vtkImageResize>::New();
    resize->SetInputConnection(heights->GetOutputPort());
    resize->SetOutputDimensions(size, size, 1);
    heights = resize;
  }
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputConnection(heights->GetOutputPort());
  relief->Update();
  return FieldOf(relief->GetOutput());
}

std::vector<Scene> Scenes()
{
  std::vector<Scene> scenes;
  scenes.push_back(MakeScene("smooth", DepthField::FromFunction(128, 128, [](float u, float v) {
    return 0.5f + 0.2f * std::sin(2.0f * float(Pi) * u) * std::cos(4.0f * float(Pi) * v);
  })));
  scenes.push_back(MakeScene("noisy", RandomField(64, 64, 11, 0.0f, 1.0f)));
  DepthField spikes = RandomField(128, 128, 12, 0.85f, 0.95f);
  std::mt19937 generator(13);
  std::uniform_int_distribution<int> texel(0, 128 * 128 - 1);
  for (int k = 0; k < 400; ++k)
  {
    spikes.Depths[static_cast<size_t>(texel(generator))] = 0.0f; // one texel wide, full height
  }
  scenes.push_back(MakeScene("spikes", spikes));
  scenes.push_back(MakeScene("cliffs", DepthField::FromFunction(128, 128, [](float u, float v) {
    return (std::fmod(4.0f * u, 1.0f) < 0.5f) != (std::fmod(3.0f * v, 1.0f) < 0.3f) ? 0.1f : 0.9f;
  })));
  DepthField checker;
  checker.Width = 32;
  checker.Height = 32;
  for (int j = 0; j < 32; ++j)
  {
    for (int i = 0; i < 32; ++i)
    {
      checker.Depths.push_back((i + j) % 2 ? 0.2f : 0.8f); // saddles in every cell
    }
  }
  scenes.push_back(MakeScene("checkerboard", checker));
  scenes.push_back(MakeScene("16-bit terrain", DataField("stones_height.png")));
  scenes.push_back(MakeScene("rivets", DataField("rivets_height.png")));
  scenes.push_back(MakeScene("non-power-of-two", RandomField(100, 37, 14, 0.3f, 1.0f)));
  return scenes;
}

// Rays from straight down to 89 degrees off the normal on a relief whose depth 1 spans
// `depthInTiles` of a tile, entering anywhere in the tile, in every azimuth.
std::vector<ReliefRay> ViewRays(unsigned seed, float depthInTiles)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<float> entry(0.0f, 1.0f);
  std::uniform_real_distribution<double> tilt(0.0, 89.0 * Pi / 180.0);
  std::uniform_real_distribution<double> azimuth(0.0, 2.0 * Pi);
  std::vector<ReliefRay> rays;
  for (int i = 0; i < RayCount; ++i)
  {
    const double run = std::tan(tilt(generator)) * depthInTiles;
    const double angle = azimuth(generator);
    rays.push_back(reliefViewRay(vec2(entry(generator), entry(generator)),
      vec3(float(run * std::cos(angle)), float(run * std::sin(angle)), 1.0f)));
  }
  return rays;
}

// Every scene, 10^4 rays each: the search's hit must be the reference's within
// `tolerance` (texels and depth). `prepare` sets whatever else the search reads.
template <typename Search>
void ExpectExact(const std::vector<Scene>& scenes, const char* method, Search search,
  double tolerance = Tolerance,
  const std::function<void(const Scene&)>& prepare = [](const Scene&) {})
{
  unsigned seed = 100;
  for (const Scene& scene : scenes)
  {
    CurrentField = &scene.Field;
    CurrentPyramid = &scene.Pyramid;
    prepare(scene);
    int wrong = 0;
    double worst = 0.0;
    long samples = 0;
    for (const ReliefRay& ray : ViewRays(seed++, 0.1f))
    {
      const double reference = ReferenceHit(scene.Field, ray);
      const ReliefHit hit = search(ray);
      const double error = HitError(scene.Field, ray, hit.t, reference);
      worst = std::max(worst, error);
      samples += hit.samples;
      if (!(error <= tolerance) || !hit.hit)
      {
        if (++wrong <= 3)
        {
          ADD_FAILURE() << method << " on " << scene.Name << ": t " << hit.t << " against "
                        << reference << " (error " << error << ") for the ray from ("
                        << ray.origin.x << ", " << ray.origin.y << ") along ("
                        << ray.direction.x << ", " << ray.direction.y << ", "
                        << ray.direction.z << ")";
        }
      }
    }
    std::cout << method << " on " << scene.Name << ": " << wrong << " of " << RayCount
              << " rays off by more than " << tolerance << ", worst " << worst << ", "
              << double(samples) / RayCount << " samples per ray\n";
    EXPECT_EQ(wrong, 0) << method << " on " << scene.Name;
  }
}

// Rays beyond 89 degrees, running 100 and 500 tiles per unit of depth: positions reach
// 10^5 texels, where floats hold a few 10^-3 texel, and on steep noise a hit is defined
// only to the depth that buys (up to 10^-2 here). An exact search must keep every hit
// within that: a walk that drifts off its cells reports hits a tenth of the depth away,
// where the ray is not (ExactDDA did).
template <typename Search>
void ExpectGrazingHits(const std::vector<Scene>& scenes, const char* method, Search search,
  const std::function<void(const Scene&)>& prepare = [](const Scene&) {})
{
  std::mt19937 generator(23);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const Scene& scene : scenes)
  {
    CurrentField = &scene.Field;
    CurrentPyramid = &scene.Pyramid;
    prepare(scene);
    int wrong = 0;
    for (int k = 0; k < 40; ++k)
    {
      const float azimuth = 2.0f * float(Pi) * unit(generator);
      const ReliefRay ray = reliefViewRay(vec2(unit(generator), unit(generator)),
        vec3(std::cos(azimuth), std::sin(azimuth), k % 2 ? 2e-3f : 1e-2f));
      const double reference = ReferenceHit(scene.Field, ray);
      const ReliefHit hit = search(ray);
      const double depthError = std::abs(hit.t - reference) * ray.direction.z;
      if (!hit.hit || !(depthError <= 1e-2))
      {
        if (++wrong <= 3)
        {
          ADD_FAILURE() << method << " on " << scene.Name << ": t " << hit.t << " against "
                        << reference << " for the grazing ray from (" << ray.origin.x << ", "
                        << ray.origin.y << ") along (" << ray.direction.x << ", "
                        << ray.direction.y << ", " << ray.direction.z << ")";
        }
      }
    }
    EXPECT_EQ(wrong, 0) << method << " on " << scene.Name << ", of 40 grazing rays";
  }
}

// Every scene with its cone map and slope pyramid, made once per test suite: the fixture
// of the searches that read cones (ConeStep, Automatic over either).
class ReliefConeScenes : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    AllScenes = new std::vector<Scene>(Scenes());
    ConeMaps = new std::vector<ConeStepMap>();
    SlopeMaps = new std::vector<SlopePyramid>();
    for (const Scene& scene : *AllScenes)
    {
      ConeMaps->push_back(ConeMapOf(scene.Field));
      SlopeMaps->push_back(SlopesOf(scene.Field));
    }
  }
  static void TearDownTestSuite()
  {
    delete AllScenes;
    delete ConeMaps;
    delete SlopeMaps;
    AllScenes = nullptr;
    ConeMaps = nullptr;
    SlopeMaps = nullptr;
  }
  static size_t Find(const std::string& name)
  {
    for (size_t k = 0; k < AllScenes->size(); ++k)
    {
      if ((*AllScenes)[k].Name == name)
      {
        return k;
      }
    }
    ADD_FAILURE() << "no scene " << name;
    return 0;
  }
  static void Use(size_t scene)
  {
    CurrentField = &(*AllScenes)[scene].Field;
    CurrentPyramid = &(*AllScenes)[scene].Pyramid;
    CurrentConeMap = &(*ConeMaps)[scene];
    CurrentSlopes = &(*SlopeMaps)[scene];
  }
  static inline std::vector<Scene>* AllScenes = nullptr;
  static inline std::vector<ConeStepMap>* ConeMaps = nullptr;
  static inline std::vector<SlopePyramid>* SlopeMaps = nullptr;
};
}

#endif

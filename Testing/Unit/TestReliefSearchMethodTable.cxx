// vtkReliefSearchMethod, the one description of each search method, against what reads
// it: ids in order and names that the mapper's enum and the mirror agree on, a GLSL
// function of the shared signature in the shader sources for each, the mirror's search
// of that function, and an acceleration filter exactly where the method reads an image.
#include "ReliefCpuMirror.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefSearchMethod.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace
{
// Every shader source of the module, concatenated.
std::string ShaderSources()
{
  std::string sources;
  for (const auto& entry : std::filesystem::directory_iterator(RELIEF_GLSL_DIR))
  {
    if (entry.path().extension() == ".glsl")
    {
      std::ifstream file(entry.path());
      std::ostringstream text;
      text << file.rdbuf();
      sources += text.str();
    }
  }
  return sources;
}

TEST(ReliefSearchMethodTable, EveryMethodIsDescribedOnceAndFoundWhereItIsRead)
{
  const std::string sources = ShaderSources();
  ASSERT_FALSE(sources.empty());
  const int count = vtkReliefSearchMethod::GetNumberOfMethods();
  EXPECT_GE(count, 7);
  std::set<std::string> names;
  for (int id = 0; id < count; ++id)
  {
    const vtkReliefSearchMethod* method = vtkReliefSearchMethod::Get(id);
    ASSERT_NE(method, nullptr);
    EXPECT_EQ(method->Id, id) << "entries in order of id";
    EXPECT_TRUE(names.insert(method->Name).second) << method->Name << " twice";
    EXPECT_EQ(vtkReliefSearchMethod::Find(method->Name), method);
    const std::string signature = std::string("ReliefHit ") + method->Function +
      "(ReliefRay ray, int linearSteps, int refinementSteps)";
    EXPECT_NE(sources.find(signature), std::string::npos)
      << method->Name << ": no " << signature << " in the shader sources";
    EXPECT_NE(ReliefCpuMirror::FindSearch(method->Function), nullptr)
      << method->Name << ": the CPU mirror has no " << method->Function;
    // SlopeMipmap's pyramid is read through an integer sampler, every other image as floats
    EXPECT_EQ(method->GetShaderDefine(),
      std::string("#define RELIEF_SEARCH ") + method->Function + "\n" +
        (id == vtkOpenGLReliefMapper::SLOPE_MIPMAP ? "#define RELIEF_ACCELERATION_CODES\n" : ""))
      << method->Name;
    auto filter = vtk::TakeSmartPointer(
      method->NewAccelerationFilter ? method->NewAccelerationFilter() : nullptr);
    EXPECT_EQ(filter != nullptr, method->NeedsAcceleration()) << method->Name;
  }
  EXPECT_EQ(vtkReliefSearchMethod::Get(-1), nullptr);
  EXPECT_EQ(vtkReliefSearchMethod::Get(count), nullptr);
  EXPECT_EQ(vtkReliefSearchMethod::Find("cone-step"), vtkReliefSearchMethod::Find("ConeStep"));
  EXPECT_EQ(vtkReliefSearchMethod::Find("Bisection"), nullptr);
}

TEST(ReliefSearchMethodTable, CurvedRaysGetTheMethodsThatFollowThemAndAutomaticsSteps)
{
  const std::string sources = ShaderSources();
  for (int id = 0; id < vtkReliefSearchMethod::GetNumberOfMethods(); ++id)
  {
    const vtkReliefSearchMethod* method = vtkReliefSearchMethod::Get(id);
    const vtkReliefSearchMethod* curved = vtkReliefSearchMethod::GetForCurvedRays(id);
    if (std::string(method->Name) != "Automatic")
    {
      EXPECT_EQ(curved, method->FollowsCurvedRays ? method : nullptr) << method->Name;
      continue;
    }
    // Automatic keeps its id and name, steps without the cone map it reads on straight rays
    ASSERT_NE(curved, nullptr);
    EXPECT_NE(curved, method);
    EXPECT_EQ(curved->Id, id);
    EXPECT_STREQ(curved->Name, method->Name);
    EXPECT_TRUE(curved->FollowsCurvedRays);
    EXPECT_FALSE(curved->NeedsAcceleration());
    EXPECT_TRUE(method->NeedsAcceleration());
    EXPECT_NE(sources.find(std::string("ReliefHit ") + curved->Function + "("), std::string::npos);
    EXPECT_NE(ReliefCpuMirror::FindSearch(curved->Function), nullptr);
  }
  EXPECT_EQ(vtkReliefSearchMethod::GetForCurvedRays(-1), nullptr);
}

TEST(ReliefSearchMethodTable, AutomaticStepsOverTheConeMapOrTheSlopePyramid)
{
  const std::string sources = ShaderSources();
  using Mapper = vtkOpenGLReliefMapper;
  const vtkReliefSearchMethod* automatic = vtkReliefSearchMethod::Get(Mapper::AUTOMATIC);
  const vtkReliefSearchMethod* slope = vtkReliefSearchMethod::Get(Mapper::SLOPE_MIPMAP);
  EXPECT_EQ(vtkReliefSearchMethod::GetAutomatic(Mapper::CONE_STEP), automatic);
  const vtkReliefSearchMethod* overSlopes =
    vtkReliefSearchMethod::GetAutomatic(Mapper::SLOPE_MIPMAP);
  ASSERT_NE(overSlopes, nullptr);
  EXPECT_NE(overSlopes, automatic);
  // Automatic still, reading SlopeMipmap's image: one pyramid for both, built once
  EXPECT_EQ(overSlopes->Id, automatic->Id);
  EXPECT_STREQ(overSlopes->Name, automatic->Name);
  EXPECT_EQ(overSlopes->GetAccelerationKind(), slope->GetAccelerationKind());
  EXPECT_EQ(overSlopes->SetUniforms, slope->SetUniforms);
  EXPECT_NE(overSlopes->GetShaderDefine().find("#define RELIEF_ACCELERATION_CODES\n"),
    std::string::npos);
  EXPECT_NE(sources.find(std::string("ReliefHit ") + overSlopes->Function +
              "(ReliefRay ray, int linearSteps, int refinementSteps)"),
    std::string::npos);
  EXPECT_NE(ReliefCpuMirror::FindSearch(overSlopes->Function), nullptr);
  for (int id :
    { -1, int(Mapper::LINEAR_BINARY), int(Mapper::MAXIMUM_MIPMAP), int(Mapper::AUTOMATIC) })
  {
    EXPECT_EQ(vtkReliefSearchMethod::GetAutomatic(id), nullptr) << id;
  }
}
}

#include "vtkReliefShaderRewrites.h"

#include <iterator>
#include <regex>

const std::vector<vtkReliefShaderRewrites::Tag>& vtkReliefShaderRewrites::GetTags()
{
  static const std::vector<Tag> tags = {
    { vtkShader::Vertex, VertexDeclarations },
    { vtkShader::Vertex, VertexEnd },
    { vtkShader::Fragment, FragmentSystem },
    { vtkShader::Fragment, FragmentDeclarations },
    { vtkShader::Fragment, FragmentStart },
    { vtkShader::Fragment, FragmentDepth },
    { vtkShader::Fragment, FragmentNormal },
    { vtkShader::Fragment, FragmentOutput },
    { vtkShader::Geometry, GeometryDeclarations },
    { vtkShader::Geometry, GeometryVertex },
  };
  return tags;
}

namespace
{
// Every occurrence of `tag` in `source` replaced, as vtkShaderProgram::Substitute does;
// false where there is none.
bool SubstituteAll(std::string& source, const char* tag, const std::string& replacement)
{
  const std::string::size_type length = std::char_traits<char>::length(tag);
  bool found = false;
  for (std::string::size_type at = source.find(tag); at != std::string::npos;
       at = source.find(tag, at + replacement.size()))
  {
    source.replace(at, length, replacement);
    found = true;
  }
  return found;
}
}

bool vtkReliefShaderRewrites::InsertAfter(
  std::string& source, const char* tag, const std::string& code)
{
  return SubstituteAll(source, tag, tag + ("\n" + code));
}

bool vtkReliefShaderRewrites::InsertBefore(
  std::string& source, const char* tag, const std::string& code)
{
  return SubstituteAll(source, tag, code + "\n  " + tag);
}

bool vtkReliefShaderRewrites::Replace(std::string& source, const char* tag, const std::string& code)
{
  return SubstituteAll(source, tag, code);
}

namespace
{
// The number of matches of `pattern` in `source`, each replaced by `replacement`.
int ReplaceAll(std::string& source, const std::regex& pattern, const std::string& replacement)
{
  const int matches = static_cast<int>(std::distance(
    std::sregex_iterator(source.begin(), source.end(), pattern), std::sregex_iterator()));
  if (matches > 0)
  {
    source = std::regex_replace(source, pattern, replacement);
  }
  return matches;
}
}

int vtkReliefShaderRewrites::WeightLightsBy(std::string& fragment, const char* visibility)
{
  // vtkOpenGLPolyDataMapper's directional lights (light complexity 2), then its
  // positional ones (3)
  const std::string weight = std::string(" * ") + visibility;
  const std::regex directional(
    R"(df = max\(0\.0, dot\(normalVCVSOutput, -lightDirectionVC(\d+)\)\);)");
  int lights = ReplaceAll(fragment, directional,
    "df = max(0.0, dot(normalVCVSOutput, -lightDirectionVC$1))" + weight +
      "(-lightDirectionVC$1);");
  const std::regex positional(
    R"(df = max\(0\.0,attenuation\*dot\(normalVCVSOutput, -vertLightDirectionVC\)\);)");
  lights += ReplaceAll(fragment, positional,
    "df = max(0.0,attenuation*dot(normalVCVSOutput, -vertLightDirectionVC))" + weight +
      "(-vertLightDirectionVC);");
  return lights;
}

int vtkReliefShaderRewrites::ReadTexturesThrough(std::string& fragment, const char* read)
{
  const std::regex implicitRead(
    std::string(R"(texture\((\w+), )") + GetTextureCoordinates() + R"(\))");
  return ReplaceAll(fragment, implicitRead,
    std::string(read) + "($1, " + GetTextureCoordinates() + ")");
}

void vtkReliefShaderRewrites::DeclareModelToView(std::string& vertex, const char* tag)
{
  const bool declared = vertex.find("uniform mat4 MCVCMatrix;") != std::string::npos;
  Replace(vertex, tag, declared ? "" : "uniform mat4 MCVCMatrix;");
}

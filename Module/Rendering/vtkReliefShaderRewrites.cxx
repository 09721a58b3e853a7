#include "vtkReliefShaderRewrites.h"

#include <cctype>
#include <functional>

const std::vector<vtkReliefShaderRewrites::Tag>& vtkReliefShaderRewrites::GetTags()
{
  static const std::vector<Tag> tags = {
    { vtkShader::Vertex, VertexDeclarations },
    { vtkShader::Vertex, VertexEnd },
    { vtkShader::Fragment, FragmentSystem },
    { vtkShader::Fragment, FragmentDeclarations },
    { vtkShader::Fragment, FragmentStart },
    { vtkShader::Fragment, FragmentDepth },
    { vtkShader::Fragment, FragmentColour },
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
// Each `before` + captured + `after` in `source`, the captured text a run of characters
// that `captures` accepts (an empty run where it is null), replaced by what `rewrite`
// makes of the captured text; the number replaced. Plain searches: std::regex took
// milliseconds per shader, which a hundred mappers built one after another paid each.
int RewriteEach(std::string& source, const std::string& before, const std::string& after,
  bool (*captures)(char), const std::function<std::string(const std::string&)>& rewrite)
{
  int rewritten = 0;
  for (std::string::size_type at = source.find(before); at != std::string::npos;
       at = source.find(before, at))
  {
    std::string::size_type end = at + before.size();
    while (captures && end < source.size() && captures(source[end]))
    {
      ++end;
    }
    const std::string captured = source.substr(at + before.size(), end - at - before.size());
    // a whole call: not the tail of a longer name, its argument and closing all there
    const bool partOfName = at > 0 &&
      (std::isalnum(static_cast<unsigned char>(source[at - 1])) != 0 || source[at - 1] == '_');
    if (partOfName || source.compare(end, after.size(), after) != 0 ||
      (captures && captured.empty()))
    {
      ++at; // not this one: search on from the next character
      continue;
    }
    const std::string replacement = rewrite(captured);
    source.replace(at, end + after.size() - at, replacement);
    at += replacement.size();
    ++rewritten;
  }
  return rewritten;
}

bool IsDigit(char c)
{
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

bool IsWordCharacter(char c)
{
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}
}

int vtkReliefShaderRewrites::LightThrough(
  std::string& fragment, const char* diffuse, const char* visibility)
{
  // vtkOpenGLPolyDataMapper's headlight (light complexity 1), its directional lights (2),
  // then its positional ones (3)
  const std::string lit = diffuse;
  const std::string weight = std::string(" * ") + visibility;
  int lights = RewriteEach(fragment, "float df = max(0.0,normalVCVSOutput.z);", "", nullptr,
    [&lit](const std::string&) { return "float df = " + lit + "(vec3(0.0, 0.0, 1.0));"; });
  // VTK 9.2 (ParaView 5.11) floors the headlight's cosine, so that pow(df, 0) stays 1
  lights += RewriteEach(fragment, "float df = max(0.000001, normalVCVSOutput.z);", "", nullptr,
    [&lit](const std::string&) {
      return "float df = max(0.000001, " + lit + "(vec3(0.0, 0.0, 1.0)));";
    });
  lights += RewriteEach(fragment, "df = max(0.0, dot(normalVCVSOutput, -lightDirectionVC",
    "));", IsDigit, [&](const std::string& light) {
      return "df = " + lit + "(-lightDirectionVC" + light + ")" + weight + "(-lightDirectionVC" +
        light + ");";
    });
  lights += RewriteEach(fragment,
    "df = max(0.0,attenuation*dot(normalVCVSOutput, -vertLightDirectionVC));", "", nullptr,
    [&](const std::string&) {
      return "df = max(0.0, attenuation) * " + lit + "(-vertLightDirectionVC)" + weight +
        "(-vertLightDirectionVC);";
    });
  return lights;
}

int vtkReliefShaderRewrites::ReadTexturesThrough(
  std::string& fragment, const char* read, const char* colourRead)
{
  const std::string coordinates = GetTextureCoordinates();
  return RewriteEach(fragment, "texture(", ", " + coordinates + ")", IsWordCharacter,
    [&](const std::string& sampler) {
      const bool colour = sampler != "normalTex" && sampler != "materialTex" &&
        sampler != "anisotropyTex" && sampler != "emissiveTex";
      return std::string(colour ? colourRead : read) + "(" + sampler + ", " + coordinates + ")";
    });
}

void vtkReliefShaderRewrites::DeclareModelToView(std::string& vertex, const char* tag)
{
  const bool declared = vertex.find("uniform mat4 MCVCMatrix;") != std::string::npos;
  Replace(vertex, tag, declared ? "" : "uniform mat4 MCVCMatrix;");
}

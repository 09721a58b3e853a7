/**
 * @class   vtkReliefShaderRewrites
 * @brief   every place where the relief mappers depend on VTK's generated shader code
 *
 * The relief mappers insert their code at tags of VTK's shader templates and rewrite a
 * few statements of the code VTK generates: its lighting (each light's diffuse term
 * weighted by the relief's self-shadow), its reads of the actor's textures (at the
 * level of the ray's entry), and the name of its texture-coordinate variable (read at
 * the hit instead). These follow VTK's sources, which differ between VTK versions (9.1
 * on Debian, 9.2 in ParaView 5.11), so they live here, each reporting whether it found
 * what it looks for; TestReliefShaderRewrites checks them against the generated code of
 * the VTK the project is built with, and the mapper warns, naming the tag or statement,
 * where one finds nothing.
 */
#ifndef vtkReliefShaderRewrites_h
#define vtkReliefShaderRewrites_h

#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkShader.h"                // For vtkShader::Type
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

#include <string> // For the sources
#include <vector> // For GetTags

class VTK_WRAPEXCLUDE VTKRELIEFRENDERING_EXPORT vtkReliefShaderRewrites
{
public:
  /// A tag of VTK's shader templates the mappers insert code at.
  struct Tag
  {
    vtkShader::Type Stage;
    const char* Name;
  };
  ///@{
  /// The tags, and each by name.
  static const std::vector<Tag>& GetTags();
  static constexpr const char* VertexDeclarations = "//VTK::PositionVC::Dec";
  static constexpr const char* VertexEnd = "//VTK::CustomEnd::Impl";
  static constexpr const char* FragmentSystem = "//VTK::System::Dec";
  static constexpr const char* FragmentDeclarations = "//VTK::Edges::Dec";
  static constexpr const char* FragmentStart = "//VTK::UniformFlow::Impl";
  static constexpr const char* FragmentDepth = "//VTK::Depth::Impl";
  static constexpr const char* FragmentColour = "//VTK::Color::Impl";
  static constexpr const char* FragmentNormal = "//VTK::Normal::Impl"; // lit surfaces only
  static constexpr const char* FragmentOutput = "//VTK::DepthPeeling::Impl";
  static constexpr const char* GeometryDeclarations = "//VTK::Normal::Dec";
  static constexpr const char* GeometryVertex = "//VTK::Normal::Impl";
  ///@}

  ///@{
  /**
   * `code` put after each `tag`, keeping the tag, so that VTK's own code still lands
   * before it; before it; or in its place. False, and `source` unchanged, where it lacks
   * the tag.
   */
  static bool InsertAfter(std::string& source, const char* tag, const std::string& code);
  static bool InsertBefore(std::string& source, const char* tag, const std::string& code);
  static bool Replace(std::string& source, const char* tag, const std::string& code);
  ///@}

  /**
   * VTK's fragment variable of the texture coordinates its texture and normal-map code
   * reads (the vertex shader's output, renamed when a geometry shader runs).
   */
  static const char* GetTextureCoordinates() { return "tcoordVCVSOutput"; }

  /**
   * In VTK's generated (non-PBR) lighting code, each light's diffuse cosine
   * max(0, dot(normal, toLight)) replaced by `diffuse`(toLight), and weighted by
   * `visibility`(toLight) for directional and positional lights (the specular term
   * follows through sign(df)); the headlight's by `diffuse`(0, 0, 1) alone (it shines
   * along the view: no self-shadow; VTK raises that same term to the specular power, so
   * its highlight follows the footprint's cosine too). Returns the number of terms
   * replaced, one per light: 0 where the code did not match.
   */
  static int LightThrough(std::string& fragment, const char* diffuse, const char* visibility);

  /**
   * VTK's implicit-derivative reads of textures at GetTextureCoordinates() made through
   * `colourRead`(sampler, coordinates), those of the physically based property's textures
   * that hold no colour it multiplies (normalTex, materialTex, anisotropyTex, emissiveTex)
   * through `read`. Returns the number of reads rewritten.
   */
  static int ReadTexturesThrough(std::string& fragment, const char* read, const char* colourRead);

  /// `tag` of the vertex shader replaced by the declaration of VTK's model-to-view
  /// matrix where VTK did not declare it (it does for lit surfaces only).
  static void DeclareModelToView(std::string& vertex, const char* tag);
};

#endif

// vtkRelief: the interpolated tangent basis (Oliveira and Policarpo 2005, s3.4) that the
// tangent and quadric frames are built on: per vertex, vtkReliefTangentFrameFilter's
// normal, tangent and texture scale (s_x, s_y, model length of one texture unit along
// tangent and bitangent), carried to view space. Written in the GLSL subset GLM also
// compiles (see vtkReliefCommon.glsl); the stage sections hold the varyings.

// A vertex's basis in view space, as the vertex stage passes it on.
struct ReliefTangentVertex
{
  vec3 normal;       // the normal matrix's image of the model normal
  vec3 tangent;      // the image of the unit model tangent (an actor's scale stretches it)
  vec2 textureScale; // s_x, s_y in view units
  vec2 stretch;      // lengths of the images of the unit model tangent and bitangent
};

// normalMatrix, directionMatrix: model to view for normals and for directions, without
// the position VBO's shift and scale.
ReliefTangentVertex reliefTangentVertex(vec3 normalMC, vec3 tangentMC, vec2 textureScaleMC,
  mat3 normalMatrix, mat3 directionMatrix)
{
  // unit, perpendicular model axes: only the actor's transform may stretch them
  vec3 unitNormal = normalize(normalMC);
  vec3 unitTangent = normalize(tangentMC - unitNormal * dot(unitNormal, tangentMC));
  vec3 tangentView = directionMatrix * unitTangent;
  vec3 bitangentView = directionMatrix * cross(unitNormal, unitTangent);
  ReliefTangentVertex basis;
  basis.normal = normalMatrix * normalMC;
  basis.tangent = tangentView;
  basis.stretch = vec2(length(tangentView), length(bitangentView));
  // an actor's scale stretches the tile as seen from the camera: carry it into s_x, s_y
  basis.textureScale = vec2(textureScaleMC.x * basis.stretch.x, textureScaleMC.y * basis.stretch.y);
  return basis;
}

#if defined(RELIEF_VERTEX_STAGE)
in vec3 reliefNormalMC;
in vec3 reliefTangentMC;
in vec2 reliefTextureScaleMC;
uniform mat3 reliefNormalMatrix;
uniform mat3 reliefDirectionMatrix;
out vec3 reliefNormalVSOutput;
out vec3 reliefTangentVSOutput;
out vec2 reliefTextureScaleVSOutput;

ReliefTangentVertex reliefTangentBasisVertex()
{
  ReliefTangentVertex basis = reliefTangentVertex(reliefNormalMC, reliefTangentMC,
    reliefTextureScaleMC, reliefNormalMatrix, reliefDirectionMatrix);
  reliefNormalVSOutput = basis.normal;
  reliefTangentVSOutput = basis.tangent;
  reliefTextureScaleVSOutput = basis.textureScale;
  return basis;
}
#elif defined(RELIEF_GEOMETRY_STAGE)
in vec3 reliefNormalVSOutput[];
in vec3 reliefTangentVSOutput[];
in vec2 reliefTextureScaleVSOutput[];
out vec3 reliefNormalGSOutput;
out vec3 reliefTangentGSOutput;
out vec2 reliefTextureScaleGSOutput;

// a macro: an unsized input array takes no function argument as index
#define reliefTangentBasisGeometry(vertex) \
  reliefNormalGSOutput = reliefNormalVSOutput[vertex]; \
  reliefTangentGSOutput = reliefTangentVSOutput[vertex]; \
  reliefTextureScaleGSOutput = reliefTextureScaleVSOutput[vertex]
#else
// A fragment's basis: unit normal, tangent and bitangent, and the texture scale.
struct ReliefTangentBasis
{
  vec3 normal;
  vec3 tangent;
  vec3 bitangent;
  vec2 textureScale;
};

ReliefTangentBasis reliefTangentBasis(vec3 normal, vec3 tangent, vec2 textureScale,
  bool frontFacing)
{
  ReliefTangentBasis basis;
  basis.normal = normalize(normal);
  basis.tangent = normalize(tangent - basis.normal * dot(basis.normal, tangent));
  basis.bitangent = cross(basis.normal, basis.tangent);
  // seen from behind, the relief is carved into the back: the normal turns, the
  // texture axes stay
  if (!frontFacing)
  {
    basis.normal = -basis.normal;
  }
  basis.textureScale = textureScale;
  if (abs(basis.textureScale.x) < 1e-20f)
  {
    basis.textureScale.x = 1e-20f;
  }
  if (abs(basis.textureScale.y) < 1e-20f)
  {
    basis.textureScale.y = 1e-20f;
  }
  return basis;
}

#if defined(RELIEF_FRAGMENT_STAGE)
in vec3 reliefNormalVSOutput;
in vec3 reliefTangentVSOutput;
in vec2 reliefTextureScaleVSOutput;

ReliefTangentBasis reliefTangentBasisOf(ReliefFragment fragment)
{
  return reliefTangentBasis(reliefNormalVSOutput, reliefTangentVSOutput,
    reliefTextureScaleVSOutput, fragment.frontFacing);
}
#endif
#endif

/**
 * @class   vtkReliefTextureFilter
 * @brief   turn a height image into a relief texture (normal and depth per texel)
 *
 * vtkReliefTextureFilter takes a 2D image of any scalar type and produces the
 * texture the relief mappers sample: a VTK_FLOAT image with the input's
 * dimensions, spacing and origin whose point scalars, named "Relief", hold
 * four components per texel, (nx, ny, nz, depth).
 *
 * Depth lies in [0, 1]: 0 at the surface (the highest height), 1 deepest.
 * Integer inputs are normalized by the range of their type, so absolute levels
 * survive and a 16-bit map keeps its 65536 levels; float inputs by the range of
 * their finite values (a constant image is flat, depth 0). Depths are then
 * rounded to the nearest k / DEPTH_LEVELS (65535), the levels of the 16-bit
 * texture the mappers search, so that the searched field, the acceleration
 * images built from this output and any geometry displaced by it agree exactly;
 * 8- and 16-bit inputs lose nothing, others at most 7.7e-6 of the depth range.
 * By default white is high (InputConvention Height);
 * SetInputConventionToDepth() reads white as deep. Non-finite heights are
 * replaced (+Inf by the highest level, -Inf and NaN by the lowest) with one
 * warning.
 *
 * The height is taken from one component of the input (Component); by default
 * the alpha of a 4-component image, the first component otherwise.
 *
 * Normals are computed from the depth by periodic central differences, because
 * the texture tiles (GL_REPEAT): the neighbours of the last column are in the
 * first column. With ddx and ddy the depth differences per texel, the normal
 * is normalize(r * ddx, r * ddy, 1), r being DepthToTexelRatio, the number of
 * texels a depth of 1 spans. It is the normal of the surface
 * (i, j, -r * depth): where depth grows toward +x the normal leans to +x. The
 * mapper rebuilds the depth gradient as n.xy / (n.z * r) and relights it with
 * its own depth scale, so for computed normals r sets the encoding precision,
 * never the look. UseInputNormals takes the normal from the input's first three
 * components instead (a normal map with the height in alpha); the mapper then
 * reads it the same way, so r must say how many texels deep the normal map's
 * author took a depth of 1 to be: r sets how steep such a map looks.
 *
 * The input must be 2D (one slice) with point scalars; anything else gives an
 * error and an empty output.
 */

#ifndef vtkReliefTextureFilter_h
#define vtkReliefTextureFilter_h

#include "vtkImageAlgorithm.h"
#include "vtkReliefFiltersModule.h" // For export macro

class VTKRELIEFFILTERS_EXPORT vtkReliefTextureFilter : public vtkImageAlgorithm
{
public:
  static vtkReliefTextureFilter* New();
  vtkTypeMacro(vtkReliefTextureFilter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The depth levels of the output: depths are multiples of 1 / DEPTH_LEVELS.
  enum
  {
    DEPTH_LEVELS = 65535
  };

  enum InputConventions
  {
    HEIGHT = 0, ///< larger values are higher (white = high)
    DEPTH = 1   ///< larger values are deeper (white = deep)
  };

  ///@{
  /**
   * How input values map to depth. Default HEIGHT: depth = 1 - normalized
   * value. DEPTH: depth = normalized value.
   */
  vtkSetClampMacro(InputConvention, int, HEIGHT, DEPTH);
  vtkGetMacro(InputConvention, int);
  void SetInputConventionToHeight() { this->SetInputConvention(HEIGHT); }
  void SetInputConventionToDepth() { this->SetInputConvention(DEPTH); }
  const char* GetInputConventionAsString();
  ///@}

  ///@{
  /**
   * Input component holding the height. Default -1, automatic: component 3
   * (alpha) of a 4-component image, component 0 otherwise.
   */
  vtkSetClampMacro(Component, int, -1, VTK_INT_MAX);
  vtkGetMacro(Component, int);
  ///@}

  ///@{
  /**
   * How many texels deep a depth of 1 is, used to encode the computed
   * normals. Default 1. Must be positive; other values are clamped to
   * [1e-6, 1e6] with a warning.
   */
  virtual void SetDepthToTexelRatio(double ratio);
  vtkGetMacro(DepthToTexelRatio, double);
  ///@}

  ///@{
  /**
   * Read the normal from the input's first three components instead of
   * computing it from the depth. Integer components are decoded from
   * [0, type max] to [-1, 1] (signed types as signed normalized values), float
   * components taken as they are; the result is normalized. Default off.
   * Ignored, with a warning, when the input has fewer than 3 components.
   */
  vtkSetMacro(UseInputNormals, vtkTypeBool);
  vtkGetMacro(UseInputNormals, vtkTypeBool);
  vtkBooleanMacro(UseInputNormals, vtkTypeBool);
  ///@}

protected:
  vtkReliefTextureFilter();
  ~vtkReliefTextureFilter() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int InputConvention = HEIGHT;
  int Component = -1;
  double DepthToTexelRatio = 1.0;
  vtkTypeBool UseInputNormals = false;

private:
  vtkReliefTextureFilter(const vtkReliefTextureFilter&) = delete;
  void operator=(const vtkReliefTextureFilter&) = delete;
};

#endif

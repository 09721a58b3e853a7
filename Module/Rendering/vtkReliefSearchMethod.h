/**
 * @class   vtkReliefSearchMethod
 * @brief   each relief search method, described once
 *
 * One description per method of vtkOpenGLReliefMapper::SearchMethods: its name, the
 * GLSL function the fragment shader calls through RELIEF_SEARCH (every search has the
 * signature ReliefHit f(ReliefRay ray, int linearSteps, int refinementSteps) and lives
 * in the search files of glsl/), whether it follows a curved ray, and the acceleration
 * image it reads besides the depth: the filter that makes it, how the GPU holds it and
 * the uniforms that describe it. The mapper and its texture helper, the CPU mirror's
 * tests, the regression tests and the bench all read this table, so adding a method is
 * its GLSL function and one entry here (and its reads in the mirror).
 */
#ifndef vtkReliefSearchMethod_h
#define vtkReliefSearchMethod_h

#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

#include <string> // For GetShaderDefine

class vtkReliefAccelerationFilter;
class vtkShaderProgram;

class VTK_WRAPEXCLUDE VTKRELIEFRENDERING_EXPORT vtkReliefSearchMethod
{
public:
  /// How the acceleration image is held on the GPU.
  enum Encodings
  {
    NO_ACCELERATION, ///< the method reads the depth texture only
    FLOAT_TEXELS,    ///< the filter's floats as they are: R32F or RG32F
    CONE_BYTES,      ///< vtkConeStepMapFilter::EncodeCone's two bytes a cell: RG8
    SLOPE_CODES      ///< vtkSlopeMipmapFilter::PackNode's four integers a node: RGBA32UI
  };

  int Id;               ///< vtkOpenGLReliefMapper::SearchMethods
  const char* Name;     ///< vtkOpenGLReliefMapper::GetSearchMethodAsString
  const char* Function; ///< the GLSL search function
  /// Samples the ray at its points wherever it goes, so it follows a curved ray (the
  /// quadric frame's); the others walk cells along a straight line in texture space.
  bool FollowsCurvedRays;
  Encodings Encoding;
  /// A new filter making the image the method reads (the caller owns it); null: none.
  vtkReliefAccelerationFilter* (*NewAccelerationFilter)();
  /// Gives that filter the mapper's setting for it (SafetyRadiusTolerance); null: none.
  void (*ConfigureFilter)(vtkReliefAccelerationFilter* filter, double tolerance);
  /// Sets the uniforms that describe the acceleration image of a relief texture of
  /// reliefSize texels; null: none.
  void (*SetUniforms)(vtkShaderProgram* program, const int reliefSize[2]);

  /// The method `id`, or null for an unknown one.
  static const vtkReliefSearchMethod* Get(int id);
  /**
   * The method `id` as it searches rays that curve (the quadric frame's): the method
   * itself if it follows them, Automatic's stepping variant (which needs no acceleration
   * image), or null where the method cannot search them.
   */
  static const vtkReliefSearchMethod* GetForCurvedRays(int id);
  /**
   * Automatic as it steps long straight runs over the image of `acceleration`: CONE_STEP's
   * cone map (Get(AUTOMATIC) itself) or SLOPE_MIPMAP's pyramid
   * (vtkOpenGLReliefMapper::AutomaticAcceleration); null for any other method.
   */
  static const vtkReliefSearchMethod* GetAutomatic(int acceleration);
  /// Methods in order of Id, from 0.
  static int GetNumberOfMethods();
  /// The method named `name` (Name, any case, dashes ignored), or null.
  static const vtkReliefSearchMethod* Find(const std::string& name);

  /**
   * The Id of the first method that reads the same acceleration image (same filter and
   * encoding): Automatic's cone map is ConeStep's, built and uploaded once for both.
   */
  int GetAccelerationKind() const;
  /// Whether the method reads an acceleration image.
  bool NeedsAcceleration() const { return this->Encoding != NO_ACCELERATION; }
  /// The fragment shader's selection of the method.
  std::string GetShaderDefine() const;
};

#endif

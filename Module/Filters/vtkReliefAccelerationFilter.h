/**
 * @class   vtkReliefAccelerationFilter
 * @brief   base of the filters that precompute what a relief search reads
 *
 * vtkMaximumMipmapFilter, vtkSlopeMipmapFilter, vtkSafetyRadiusFilter and
 * vtkConeStepMapFilter turn a relief height field into an image the mapper uploads as a
 * texture. They share what this class does: read the depths from vtkReliefTextureFilter's
 * output (four components, depth in the last) or from a one-component depth image, ask
 * for the whole input whatever part of the output is requested (every value may depend on
 * the whole map), report an unusable input as one error with an empty output, and produce
 * a VTK_FLOAT image with its origin at 0 and the input's spacing. Subclasses say how large the output is and
 * compute it; long computations run their rows through ForRows, which shares them among
 * threads with vtkSMPTools and reports progress between slices, from the calling thread
 * (observers may touch a GUI).
 */
#ifndef vtkReliefAccelerationFilter_h
#define vtkReliefAccelerationFilter_h

#include "vtkImageAlgorithm.h"
#include "vtkReliefFiltersModule.h" // For export macro

#include <functional> // For ForRows

class vtkFloatArray;
class vtkReliefDepthImage;

class VTKRELIEFFILTERS_EXPORT vtkReliefAccelerationFilter : public vtkImageAlgorithm
{
public:
  vtkTypeMacro(vtkReliefAccelerationFilter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * What the output of a width x height height map is: its size (the same by default)
   * and its components per texel. The mapper checks precomputed images against them.
   */
  virtual void GetOutputSize(int width, int height, int size[2]);
  virtual int GetOutputComponents() = 0;
  ///@}

protected:
  vtkReliefAccelerationFilter() = default;
  ~vtkReliefAccelerationFilter() override = default;

  /// What the filter builds, for messages: "a maximum mipmap".
  virtual const char* GetProductName() = 0;

  /// Fills `output`, sized and named by the caller, from the field.
  virtual void Compute(const vtkReliefDepthImage& field, vtkFloatArray* output) = 0;

  /// Name of the output scalars.
  virtual const char* GetOutputName() = 0;

  /**
   * Runs work(begin, end) over rows [0, rows) on vtkSMPTools' threads, in `slices`
   * slices, reporting progress from `fromProgress` to `toProgress` between them; stops
   * early when the filter is aborted.
   */
  void ForRows(int rows, int slices, double fromProgress, double toProgress,
    const std::function<void(int begin, int end)>& work);

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkReliefAccelerationFilter(const vtkReliefAccelerationFilter&) = delete;
  void operator=(const vtkReliefAccelerationFilter&) = delete;
};

#endif

/**
 * @class   vtkReliefWholeImagesAlgorithm
 * @brief   a vtkAlgorithm whose outputs are images made whole, in one piece
 *
 * The pipeline's part of the filters that make texture images from other data
 * (vtkPathFeatureTextureFilter, vtkReliefImpostorFilter): every output port holds a
 * vtkImageData whose size is known only once the inputs are read, so no output is
 * streamed (CAN_PRODUCE_SUB_EXTENT is 0 on every port), and ProcessRequest answers
 * REQUEST_INFORMATION and REQUEST_DATA through RequestInformation and RequestData. A
 * subclass says which inputs it takes (FillInputPortInformation, the number of ports)
 * and makes its images in RequestData.
 */
#ifndef vtkReliefWholeImagesAlgorithm_h
#define vtkReliefWholeImagesAlgorithm_h

#include "vtkAlgorithm.h"
#include "vtkReliefFiltersModule.h" // For export macro

class VTKRELIEFFILTERS_EXPORT vtkReliefWholeImagesAlgorithm : public vtkAlgorithm
{
public:
  vtkTypeMacro(vtkReliefWholeImagesAlgorithm, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

protected:
  vtkReliefWholeImagesAlgorithm() = default;
  ~vtkReliefWholeImagesAlgorithm() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  /// Every output whole, one piece, not streamed.
  virtual int RequestInformation(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs);
  virtual int RequestData(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) = 0;

private:
  vtkReliefWholeImagesAlgorithm(const vtkReliefWholeImagesAlgorithm&) = delete;
  void operator=(const vtkReliefWholeImagesAlgorithm&) = delete;
};

#endif

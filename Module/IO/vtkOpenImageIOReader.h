/**
 * @class   vtkOpenImageIOReader
 * @brief   read any image OpenImageIO reads into a 2D vtkImageData
 *
 * vtkOpenImageIOReader reads the first subimage of any file OpenImageIO can
 * open (PNG, TGA, TIFF, OpenEXR, JPEG, HDR, DDS, ...) without converting it:
 * the bit depth and the channel count of the file are kept, because relief
 * textures need every level of a 16-bit or float height map.
 *
 * | file channel type            | VTK scalar type      |
 * | ---------------------------- | -------------------- |
 * | UINT8 / INT8                 | VTK_UNSIGNED_CHAR / VTK_SIGNED_CHAR |
 * | UINT16 / INT16               | VTK_UNSIGNED_SHORT / VTK_SHORT |
 * | UINT32 / INT32               | VTK_UNSIGNED_INT / VTK_INT |
 * | UINT64 / INT64               | VTK_UNSIGNED_LONG_LONG / VTK_LONG_LONG |
 * | HALF / FLOAT                 | VTK_FLOAT            |
 * | DOUBLE                       | VTK_DOUBLE           |
 *
 * The output has dimensions width x height x 1, spacing 1 and origin 0; its
 * point scalars, named "OpenImageIO", hold every channel of the file. Rows
 * follow VTK's lower-left convention: the first row of the output is the
 * bottom row of the picture. Colour values are returned as stored: alpha is
 * never premultiplied into the colour channels (an RGBA texture often holds a
 * normal in RGB and a height in A, which premultiplication would corrupt).
 *
 * A file that cannot be read gives an error naming OpenImageIO's reason and
 * an empty output; setting a readable file name afterwards restores the
 * pipeline.
 */

#ifndef vtkOpenImageIOReader_h
#define vtkOpenImageIOReader_h

#include "vtkImageAlgorithm.h"
#include "vtkReliefIOModule.h" // For export macro

class VTKRELIEFIO_EXPORT vtkOpenImageIOReader : public vtkImageAlgorithm
{
public:
  static vtkOpenImageIOReader* New();
  vtkTypeMacro(vtkOpenImageIOReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Path of the image file to read.
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /**
   * Return 3 when OpenImageIO can open the file as an image, 0 otherwise
   * (the vtkImageReader2::CanReadFile convention).
   */
  virtual int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkOpenImageIOReader();
  ~vtkOpenImageIOReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkOpenImageIOReader(const vtkOpenImageIOReader&) = delete;
  void operator=(const vtkOpenImageIOReader&) = delete;

  // Set by RequestInformation so that RequestData reports a bad file once per
  // update instead of twice.
  bool InformationFailed = false;
};

#endif

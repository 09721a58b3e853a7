#include "vtkOpenImageIOReader.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>

vtkStandardNewMacro(vtkOpenImageIOReader);

namespace
{
// What the file holds, in VTK terms.
struct ImageLayout
{
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  int VTKType = VTK_VOID;
  // The type OpenImageIO converts to while reading: the file's own type,
  // except HALF, which VTK has no array for.
  OIIO::TypeDesc ReadType;
};

bool DescribeImage(const OIIO::ImageSpec& spec, ImageLayout& layout, std::string& why)
{
  layout.Width = spec.width;
  layout.Height = spec.height;
  layout.Channels = spec.nchannels;
  layout.ReadType = OIIO::TypeDesc(static_cast<OIIO::TypeDesc::BASETYPE>(spec.format.basetype));
  switch (spec.format.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      layout.VTKType = VTK_UNSIGNED_CHAR;
      break;
    case OIIO::TypeDesc::INT8:
      layout.VTKType = VTK_SIGNED_CHAR;
      break;
    case OIIO::TypeDesc::UINT16:
      layout.VTKType = VTK_UNSIGNED_SHORT;
      break;
    case OIIO::TypeDesc::INT16:
      layout.VTKType = VTK_SHORT;
      break;
    case OIIO::TypeDesc::UINT32:
      layout.VTKType = VTK_UNSIGNED_INT;
      break;
    case OIIO::TypeDesc::INT32:
      layout.VTKType = VTK_INT;
      break;
    case OIIO::TypeDesc::UINT64:
      layout.VTKType = VTK_UNSIGNED_LONG_LONG;
      break;
    case OIIO::TypeDesc::INT64:
      layout.VTKType = VTK_LONG_LONG;
      break;
    case OIIO::TypeDesc::HALF:
    case OIIO::TypeDesc::FLOAT:
      layout.VTKType = VTK_FLOAT;
      layout.ReadType = OIIO::TypeDesc::FLOAT;
      break;
    case OIIO::TypeDesc::DOUBLE:
      layout.VTKType = VTK_DOUBLE;
      break;
    default:
      why = std::string("its pixel type ") + spec.format.c_str() +
        " has no VTK equivalent; convert it, e.g. with oiiotool -d float";
      return false;
  }
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
  {
    why = "it holds no pixels";
    return false;
  }
  if (spec.depth > 1)
  {
    why = "it is a volume image (depth " + std::to_string(spec.depth) +
      ") and this reader makes 2D images; save one slice as its own file";
    return false;
  }
  return true;
}

// Alpha stays as stored: OpenImageIO premultiplies PNG and some TIFF colour by
// alpha unless told not to, which would corrupt a normal map kept in RGB.
std::unique_ptr<OIIO::ImageInput> OpenImage(const char* fileName, std::string& why)
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(fileName, &config);
  if (!in)
  {
    why = OIIO::geterror();
    if (why.empty())
    {
      why = "OpenImageIO gave no reason";
    }
  }
  return in;
}

// OpenImageIO stops reading when this returns true; a reader never asks it to.
bool ForwardProgress(void* reader, float portion)
{
  static_cast<vtkOpenImageIOReader*>(reader)->UpdateProgress(portion);
  return false;
}
}

//------------------------------------------------------------------------------
vtkOpenImageIOReader::vtkOpenImageIOReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOpenImageIOReader::~vtkOpenImageIOReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkOpenImageIOReader::CanReadFile(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return 0;
  }
  std::string why;
  auto in = OpenImage(fileName, why);
  if (!in)
  {
    return 0;
  }
  ImageLayout layout;
  return DescribeImage(in->spec(), layout, why) ? 3 : 0;
}

//------------------------------------------------------------------------------
int vtkOpenImageIOReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int emptyExtent[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), emptyExtent, 6);
  this->InformationFailed = true;

  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name: call SetFileName() with the path of an image before Update().");
    return 1;
  }
  std::string why;
  auto in = OpenImage(this->FileName, why);
  ImageLayout layout;
  if (!in || !DescribeImage(in->spec(), layout, why))
  {
    vtkErrorMacro("Cannot read \"" << this->FileName << "\": " << why
                                   << ". Check the path and that the file is an image "
                                      "OpenImageIO reads (oiiotool --info prints what it sees).");
    return 1;
  }

  const int extent[6] = { 0, layout.Width - 1, 0, layout.Height - 1, 0, 0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, layout.VTKType, layout.Channels);
  this->InformationFailed = false;
  return 1;
}

//------------------------------------------------------------------------------
int vtkOpenImageIOReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (this->InformationFailed)
  {
    return 1;
  }
  this->UpdateProgress(0.0);

  // The file is opened again: it may have changed since RequestInformation.
  std::string why;
  auto in = OpenImage(this->FileName, why);
  ImageLayout layout;
  if (!in || !DescribeImage(in->spec(), layout, why))
  {
    vtkErrorMacro("Cannot read \"" << this->FileName << "\": " << why
                                   << ". Check that the file still exists and is an image.");
    return 1;
  }

  vtkSmartPointer<vtkDataArray> scalars =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(layout.VTKType));
  scalars->SetName("OpenImageIO");
  scalars->SetNumberOfComponents(layout.Channels);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(layout.Width) * layout.Height);

  // OpenImageIO stores rows top-down and VTK bottom-up: start at the last row
  // of the array and walk backwards with a negative row stride.
  const OIIO::stride_t pixelBytes =
    static_cast<OIIO::stride_t>(layout.Channels) * layout.ReadType.size();
  const OIIO::stride_t rowBytes = pixelBytes * layout.Width;
  char* lastRow =
    static_cast<char*>(scalars->GetVoidPointer(0)) + rowBytes * (layout.Height - 1);
  if (!in->read_image(0, 0, 0, layout.Channels, layout.ReadType, lastRow, pixelBytes, -rowBytes,
        OIIO::AutoStride, &ForwardProgress, this))
  {
    std::string readError = in->geterror();
    vtkErrorMacro("Cannot read the pixels of \""
      << this->FileName << "\": " << (readError.empty() ? "OpenImageIO gave no reason" : readError)
      << ". The file is probably truncated or corrupt; re-export it.");
    return 1;
  }

  output->SetExtent(0, layout.Width - 1, 0, layout.Height - 1, 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->GetPointData()->SetScalars(scalars);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenImageIOReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}

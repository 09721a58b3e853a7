// vtkOpenImageIOReader: every file is written here with OpenImageIO, read back
// and compared value by value, with the rows flipped to VTK's lower-left origin.

#include "ReliefEventRecorder.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkOpenImageIOReader.h"
#include "vtkPointData.h"
#include "vtkReliefTextureFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

class OpenImageIOReaderTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device random;
    this->Directory = fs::temp_directory_path() /
      ("vtkRelief-reader-" + std::to_string(random()) + "-" + std::to_string(random()));
    fs::create_directories(this->Directory);
  }

  void TearDown() override
  {
    std::error_code ignored;
    fs::remove_all(this->Directory, ignored);
  }

  std::string Path(const std::string& name) const { return (this->Directory / name).string(); }

  fs::path Directory;
};

// Pixel (x, y, c) of a test picture, y counted from the top as files store it.
using PixelFunction = double (*)(int x, int y, int c);

template <typename T>
void Store(double value, unsigned char* destination)
{
  const T typed = static_cast<T>(value);
  std::memcpy(destination, &typed, sizeof(T));
}

void StoreAs(OIIO::TypeDesc type, double value, unsigned char* destination)
{
  switch (type.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      Store<std::uint8_t>(value, destination);
      break;
    case OIIO::TypeDesc::INT8:
      Store<std::int8_t>(value, destination);
      break;
    case OIIO::TypeDesc::UINT16:
      Store<std::uint16_t>(value, destination);
      break;
    case OIIO::TypeDesc::INT16:
      Store<std::int16_t>(value, destination);
      break;
    case OIIO::TypeDesc::UINT32:
      Store<std::uint32_t>(value, destination);
      break;
    case OIIO::TypeDesc::INT32:
      Store<std::int32_t>(value, destination);
      break;
    case OIIO::TypeDesc::FLOAT:
      Store<float>(value, destination);
      break;
    case OIIO::TypeDesc::DOUBLE:
      Store<double>(value, destination);
      break;
    default:
      FAIL() << "no test writer for " << type.c_str();
  }
}

// Writes a picture given top row first, as OpenImageIO expects, in `fileType`
// per channel; the values are given in double and converted by OpenImageIO.
void WritePicture(const std::string& path, int width, int height, int channels,
  OIIO::TypeDesc fileType, PixelFunction pixel, int subimages = 1)
{
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  std::vector<OIIO::ImageSpec> specs;
  for (int s = 0; s < subimages; ++s)
  {
    // Each later subimage is one pixel larger and brighter, so reading the
    // wrong one shows.
    OIIO::ImageSpec spec(width + s, height + s, channels, fileType);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.attribute("Compression", "none");
    spec.attribute("CompressionQuality", 100);
    specs.push_back(spec);
  }
  ASSERT_TRUE(subimages == 1 ? out->open(path, specs[0])
                             : out->open(path, subimages, specs.data()))
    << out->geterror();
  for (int s = 0; s < subimages; ++s)
  {
    const OIIO::ImageSpec& spec = specs[s];
    if (s > 0)
    {
      ASSERT_TRUE(out->open(path, spec, OIIO::ImageOutput::AppendSubimage)) << out->geterror();
    }
    std::vector<double> values;
    for (int y = 0; y < spec.height; ++y)
    {
      for (int x = 0; x < spec.width; ++x)
      {
        for (int c = 0; c < channels; ++c)
        {
          values.push_back(pixel(x, y, c) + s);
        }
      }
    }
    // OpenImageIO scales when it converts between integer and float types,
    // so the values are handed over in the file's own type (float for half).
    const OIIO::TypeDesc memoryType =
      fileType == OIIO::TypeDesc::HALF ? OIIO::TypeDesc(OIIO::TypeDesc::FLOAT) : fileType;
    std::vector<unsigned char> bytes(values.size() * memoryType.size());
    for (size_t i = 0; i < values.size(); ++i)
    {
      StoreAs(memoryType, values[i], bytes.data() + i * memoryType.size());
    }
    ASSERT_TRUE(out->write_image(memoryType, bytes.data())) << out->geterror();
  }
  ASSERT_TRUE(out->close()) << out->geterror();
}

vtkSmartPointer<vtkImageData> Read(vtkOpenImageIOReader* reader, const std::string& path)
{
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

// Checks the layout of a read picture and every value against `pixel`,
// within `tolerance`; the picture's row y is the image's row height - 1 - y.
void ExpectPicture(vtkImageData* image, int width, int height, int channels, int vtkType,
  PixelFunction pixel, double tolerance = 0.0)
{
  ASSERT_NE(image, nullptr);
  int dimensions[3];
  image->GetDimensions(dimensions);
  EXPECT_EQ(dimensions[0], width);
  EXPECT_EQ(dimensions[1], height);
  EXPECT_EQ(dimensions[2], 1);
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_EQ(spacing[axis], 1.0);
    EXPECT_EQ(origin[axis], 0.0);
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  ASSERT_NE(scalars, nullptr);
  EXPECT_STREQ(scalars->GetName(), "OpenImageIO");
  EXPECT_EQ(scalars->GetDataType(), vtkType) << scalars->GetDataTypeAsString();
  ASSERT_EQ(scalars->GetNumberOfComponents(), channels);
  ASSERT_EQ(scalars->GetNumberOfTuples(), static_cast<vtkIdType>(width) * height);
  int mismatches = 0;
  for (int y = 0; y < height && mismatches < 10; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < channels; ++c)
      {
        const double expected = pixel(x, y, c);
        const double actual = image->GetScalarComponentAsDouble(x, height - 1 - y, 0, c);
        if (!(std::abs(actual - expected) <= tolerance))
        {
          ++mismatches;
          ADD_FAILURE() << "picture pixel (" << x << ", " << y << ") channel " << c << ": read "
                        << actual << ", expected " << expected;
        }
      }
    }
  }
}

// 8-bit values that differ per pixel and channel; pixel (0, 0) has alpha 0 so
// that any premultiplication by alpha would zero its colour.
double Bytes(int x, int y, int c)
{
  return (x == 0 && y == 0 && c == 3) ? 0.0 : (x * 37 + y * 11 + c * 53 + 3) % 256;
}

double GreyAlphaBytes(int x, int y, int c)
{
  return (x == 0 && y == 0 && c == 1) ? 0.0 : Bytes(x, y, c);
}

double Shorts(int x, int y, int c)
{
  // Reaches both ends of the range and neighbouring levels.
  static const double levels[] = { 0, 1, 2, 255, 256, 32767, 32768, 65534, 65535, 4097 };
  return levels[(x + 3 * y + 7 * c) % 10];
}

double Halves(int x, int y, int c)
{
  // Exactly representable in half precision.
  static const double levels[] = { 0.0, -2.5, 0.125, 1000.0, 65504.0, 6.103515625e-05, 1.0 };
  return levels[(x + 2 * y + 3 * c) % 7];
}

double Floats(int x, int y, int c)
{
  return static_cast<float>(0.1 * x - 3.25e-5 * y + 1e10 * (x == 1 && y == 1) + 7.0 * c);
}

// Values every depth can hold, used for the signed and 32-bit types.
double Signed8(int x, int y, int c)
{
  static const double levels[] = { -128, -1, 0, 1, 127, 64 };
  return levels[(x + 2 * y + c) % 6];
}

double Signed16(int x, int y, int c)
{
  static const double levels[] = { -32768, -1, 0, 1, 32767, 1234 };
  return levels[(x + 2 * y + c) % 6];
}

double Signed32(int x, int y, int c)
{
  static const double levels[] = { -2147483648.0, -1, 0, 1, 2147483647.0, 123456789 };
  return levels[(x + 2 * y + c) % 6];
}

double Unsigned32(int x, int y, int c)
{
  static const double levels[] = { 0, 1, 65536, 4294967295.0, 2147483648.0, 99 };
  return levels[(x + 2 * y + c) % 6];
}

double Doubles(int x, int y, int c)
{
  return 0.1 * x + 1e-300 * y - 1e300 * (x == 2 && y == 0) + c / 3.0;
}

// Smooth enough that JPEG at quality 100 stays within a few levels.
double Gradient(int x, int y, int c)
{
  return 30 + 6 * x + 4 * y + 20 * c;
}

// A picture whose top row is white and the rest black.
double WhiteTopRow(int, int y, int)
{
  return y == 0 ? 255.0 : 0.0;
}
}

TEST_F(OpenImageIOReaderTest, Png8BitKeepsEveryChannelCountAndValue)
{
  for (int channels = 1; channels <= 4; ++channels)
  {
    SCOPED_TRACE("channels " + std::to_string(channels));
    PixelFunction pixel = channels == 2 ? GreyAlphaBytes : Bytes;
    const std::string path = this->Path("bytes" + std::to_string(channels) + ".png");
    WritePicture(path, 7, 5, channels, OIIO::TypeDesc::UINT8, pixel);
    vtkNew<vtkOpenImageIOReader> reader;
    ExpectPicture(Read(reader, path), 7, 5, channels, VTK_UNSIGNED_CHAR, pixel);
  }
}

TEST_F(OpenImageIOReaderTest, Png16BitKeepsEveryLevel)
{
  const std::string path = this->Path("shorts.png");
  WritePicture(path, 6, 4, 1, OIIO::TypeDesc::UINT16, Shorts);
  vtkNew<vtkOpenImageIOReader> reader;
  ExpectPicture(Read(reader, path), 6, 4, 1, VTK_UNSIGNED_SHORT, Shorts);
}

TEST_F(OpenImageIOReaderTest, Tiff16BitRgb)
{
  const std::string path = this->Path("shorts.tif");
  WritePicture(path, 5, 3, 3, OIIO::TypeDesc::UINT16, Shorts);
  vtkNew<vtkOpenImageIOReader> reader;
  ExpectPicture(Read(reader, path), 5, 3, 3, VTK_UNSIGNED_SHORT, Shorts);
}

TEST_F(OpenImageIOReaderTest, ExrHalfBecomesFloat)
{
  const std::string path = this->Path("halves.exr");
  WritePicture(path, 5, 4, 3, OIIO::TypeDesc::HALF, Halves);
  vtkNew<vtkOpenImageIOReader> reader;
  ExpectPicture(Read(reader, path), 5, 4, 3, VTK_FLOAT, Halves);
}

TEST_F(OpenImageIOReaderTest, ExrFloat)
{
  const std::string path = this->Path("floats.exr");
  WritePicture(path, 4, 3, 1, OIIO::TypeDesc::FLOAT, Floats);
  vtkNew<vtkOpenImageIOReader> reader;
  ExpectPicture(Read(reader, path), 4, 3, 1, VTK_FLOAT, Floats);
}

TEST_F(OpenImageIOReaderTest, TiffSignedIntegerUnsigned32AndDoubleTypes)
{
  struct Case
  {
    OIIO::TypeDesc FileType;
    int VTKType;
    PixelFunction Pixel;
  };
  const Case cases[] = {
    { OIIO::TypeDesc::INT8, VTK_SIGNED_CHAR, Signed8 },
    { OIIO::TypeDesc::INT16, VTK_SHORT, Signed16 },
    { OIIO::TypeDesc::INT32, VTK_INT, Signed32 },
    { OIIO::TypeDesc::UINT32, VTK_UNSIGNED_INT, Unsigned32 },
    { OIIO::TypeDesc::DOUBLE, VTK_DOUBLE, Doubles },
  };
  for (const Case& test : cases)
  {
    SCOPED_TRACE(test.FileType.c_str());
    const std::string path = this->Path(std::string("typed-") + test.FileType.c_str() + ".tif");
    WritePicture(path, 4, 3, 2, test.FileType, test.Pixel);
    vtkNew<vtkOpenImageIOReader> reader;
    ExpectPicture(Read(reader, path), 4, 3, 2, test.VTKType, test.Pixel);
  }
}

TEST_F(OpenImageIOReaderTest, MoreThanFourChannelsAreKept)
{
  const std::string path = this->Path("six.exr");
  WritePicture(path, 3, 2, 6, OIIO::TypeDesc::FLOAT, Floats);
  vtkNew<vtkOpenImageIOReader> reader;
  ExpectPicture(Read(reader, path), 3, 2, 6, VTK_FLOAT, Floats);
}

TEST_F(OpenImageIOReaderTest, TgaRgbAndRgba)
{
  for (int channels : { 3, 4 })
  {
    SCOPED_TRACE("channels " + std::to_string(channels));
    const std::string path = this->Path("bytes" + std::to_string(channels) + ".tga");
    WritePicture(path, 6, 5, channels, OIIO::TypeDesc::UINT8, Bytes);
    vtkNew<vtkOpenImageIOReader> reader;
    ExpectPicture(Read(reader, path), 6, 5, channels, VTK_UNSIGNED_CHAR, Bytes);
  }
}

TEST_F(OpenImageIOReaderTest, JpegWithinLossyTolerance)
{
  for (int channels : { 1, 3 })
  {
    SCOPED_TRACE("channels " + std::to_string(channels));
    const std::string path = this->Path("gradient" + std::to_string(channels) + ".jpg");
    WritePicture(path, 16, 16, channels, OIIO::TypeDesc::UINT8, Gradient);
    vtkNew<vtkOpenImageIOReader> reader;
    ExpectPicture(Read(reader, path), 16, 16, channels, VTK_UNSIGNED_CHAR, Gradient, 6.0);
  }
}

TEST_F(OpenImageIOReaderTest, TopRowOfThePictureIsTheLastRowOfTheImage)
{
  const std::string path = this->Path("top.png");
  WritePicture(path, 4, 3, 1, OIIO::TypeDesc::UINT8, WhiteTopRow);
  vtkNew<vtkOpenImageIOReader> reader;
  vtkImageData* image = Read(reader, path);
  ASSERT_EQ(image->GetNumberOfPoints(), 12);
  for (int x = 0; x < 4; ++x)
  {
    EXPECT_EQ(image->GetScalarComponentAsDouble(x, 2, 0, 0), 255.0);
    EXPECT_EQ(image->GetScalarComponentAsDouble(x, 1, 0, 0), 0.0);
    EXPECT_EQ(image->GetScalarComponentAsDouble(x, 0, 0, 0), 0.0);
  }
}

TEST_F(OpenImageIOReaderTest, ReadsOnlyTheFirstSubimage)
{
  const std::string path = this->Path("layers.tif");
  WritePicture(path, 4, 3, 1, OIIO::TypeDesc::UINT8, Bytes, 2);
  {
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    ASSERT_TRUE(in->seek_subimage(1, 0)) << "the test file should hold two subimages";
  }
  vtkNew<vtkOpenImageIOReader> reader;
  ExpectPicture(Read(reader, path), 4, 3, 1, VTK_UNSIGNED_CHAR, Bytes);
}

TEST_F(OpenImageIOReaderTest, InformationIsPublishedBeforeTheData)
{
  const std::string path = this->Path("info.png");
  WritePicture(path, 9, 7, 2, OIIO::TypeDesc::UINT16, Shorts);
  vtkNew<vtkOpenImageIOReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  vtkInformation* outInfo = reader->GetOutputInformation(0);
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  const int expected[6] = { 0, 8, 0, 6, 0, 0 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(extent[i], expected[i]) << "extent index " << i;
  }
  vtkInformation* scalarInfo = vtkDataObject::GetActiveFieldInformation(
    outInfo, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  ASSERT_NE(scalarInfo, nullptr);
  EXPECT_EQ(scalarInfo->Get(vtkDataObject::FIELD_ARRAY_TYPE()), VTK_UNSIGNED_SHORT);
  EXPECT_EQ(scalarInfo->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()), 2);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << "no pixel is read yet";
}

TEST_F(OpenImageIOReaderTest, CanReadFile)
{
  const std::string path = this->Path("can.png");
  WritePicture(path, 2, 2, 1, OIIO::TypeDesc::UINT8, Bytes);
  const std::string garbage = this->Path("garbage.png");
  std::ofstream(garbage) << "this is not a PNG file";
  vtkNew<vtkOpenImageIOReader> reader;
  EXPECT_EQ(reader->CanReadFile(path.c_str()), 3);
  EXPECT_EQ(reader->CanReadFile(garbage.c_str()), 0);
  EXPECT_EQ(reader->CanReadFile(this->Path("missing.png").c_str()), 0);
  EXPECT_EQ(reader->CanReadFile(nullptr), 0);
}

TEST_F(OpenImageIOReaderTest, MissingFileGivesErrorAndEmptyOutputThenRecovers)
{
  const std::string good = this->Path("good.png");
  const std::string missing = this->Path("missing.png");
  WritePicture(good, 3, 2, 1, OIIO::TypeDesc::UINT8, Bytes);
  vtkNew<vtkOpenImageIOReader> reader;
  vtkNew<ReliefEventRecorder> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  ExpectPicture(Read(reader, good), 3, 2, 1, VTK_UNSIGNED_CHAR, Bytes);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 0);

  // OpenImageIO's own reason must reach the user.
  ASSERT_FALSE(OIIO::ImageInput::open(missing));
  const std::string reason = OIIO::geterror();
  ASSERT_FALSE(reason.empty());

  EXPECT_EQ(Read(reader, missing)->GetNumberOfPoints(), 0);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(errors->AnyMessageContains(missing));
  EXPECT_TRUE(errors->AnyMessageContains(reason)) << "expected OpenImageIO's text: " << reason;

  errors->Clear();
  ExpectPicture(Read(reader, good), 3, 2, 1, VTK_UNSIGNED_CHAR, Bytes);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 0);
}

TEST_F(OpenImageIOReaderTest, GarbageFileGivesErrorAndEmptyOutputThenRecovers)
{
  const std::string good = this->Path("good.tif");
  const std::string garbage = this->Path("garbage.png");
  WritePicture(good, 3, 4, 2, OIIO::TypeDesc::UINT16, Shorts);
  std::ofstream(garbage, std::ios::binary) << "\x89PNG but then nothing a PNG holds";
  vtkNew<vtkOpenImageIOReader> reader;
  vtkNew<ReliefEventRecorder> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);

  EXPECT_EQ(Read(reader, garbage)->GetNumberOfPoints(), 0);
  EXPECT_GE(errors->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(errors->AnyMessageContains(garbage));

  errors->Clear();
  ExpectPicture(Read(reader, good), 3, 4, 2, VTK_UNSIGNED_SHORT, Shorts);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 0);
}

TEST_F(OpenImageIOReaderTest, DownstreamPipelineRecoversWhenTheFileNameIsFixed)
{
  const std::string good = this->Path("height.png");
  WritePicture(good, 4, 4, 1, OIIO::TypeDesc::UINT16, Shorts);
  vtkNew<vtkOpenImageIOReader> reader;
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputConnection(reader->GetOutputPort());
  vtkNew<ReliefEventRecorder> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  relief->AddObserver(vtkCommand::ErrorEvent, errors);

  reader->SetFileName(this->Path("missing.png").c_str());
  relief->Update();
  EXPECT_EQ(relief->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_GE(errors->Count(vtkCommand::ErrorEvent), 1);

  errors->Clear();
  reader->SetFileName(good.c_str());
  relief->Update();
  EXPECT_EQ(relief->GetOutput()->GetNumberOfPoints(), 16);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 0);
}

TEST_F(OpenImageIOReaderTest, NoFileNameGivesErrorAndEmptyOutput)
{
  vtkNew<vtkOpenImageIOReader> reader;
  vtkNew<ReliefEventRecorder> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(errors->AnyMessageContains("SetFileName"));
}

TEST_F(OpenImageIOReaderTest, ReportsProgressFromStartToEnd)
{
  const std::string path = this->Path("progress.png");
  WritePicture(path, 64, 64, 1, OIIO::TypeDesc::UINT8, Bytes);
  vtkNew<vtkOpenImageIOReader> reader;
  vtkNew<ReliefEventRecorder> progress;
  reader->AddObserver(vtkCommand::ProgressEvent, progress);
  Read(reader, path);
  ASSERT_GE(progress->Progress.size(), 2u);
  EXPECT_EQ(progress->Progress.front(), 0.0);
  EXPECT_EQ(progress->Progress.back(), 1.0);
}

TEST_F(OpenImageIOReaderTest, PrintSelfShowsTheFileName)
{
  vtkNew<vtkOpenImageIOReader> reader;
  reader->SetFileName("some/height.exr");
  std::ostringstream printed;
  reader->Print(printed);
  EXPECT_NE(printed.str().find("FileName: some/height.exr"), std::string::npos);
}

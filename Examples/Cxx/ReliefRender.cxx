// ReliefRender: the program behind `./relief render`. Renders a user's mesh with a
// height map as relief (vtkOpenGLReliefMapper) into a PNG and reports how long the
// render took. `ReliefRender --help` lists the options. The look (material, light,
// background) is the one of the project's scenes, ReliefScene.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkImageShiftScale.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkOpenImageIOReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTextureMapToCylinder.h"
#include "vtkTextureMapToPlane.h"
#include "vtkTextureMapToSphere.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <string>

namespace
{
// Exit codes: 2 for a command line that cannot be understood (as GNU tools do),
// 1 for a file that cannot be read or written.
constexpr int UsageFailure = 2;
constexpr int RunFailure = 1;

struct Options
{
  std::string MeshFile;
  std::string HeightFile;
  std::string ColorFile;
  std::optional<double> DepthScale; // unset: a fraction of the mesh's size
  double Tiles[2] = { 1.0, 1.0 }; // along u and v
  std::string TextureMap; // empty: keep the mesh's own texture coordinates
  bool DepthConvention = false;
  int SearchMethod = vtkOpenGLReliefMapper::AUTOMATIC;
  double ScreenTolerance = 0.5;
  int AutomaticAcceleration = vtkOpenGLReliefMapper::CONE_STEP;
  int LinearSteps = 10;
  int BinarySteps = 5;
  double SafetyTolerance = 0.0;
  bool Shadows = true;
  bool FootprintShading = true;
  bool Quadric = false; // the curved frame: the relief carves the silhouette
  bool Derivative = false; // the frame from screen-space derivatives: no tangents
  double Azimuth = 0.0;
  double Elevation = 0.0;
  double Zoom = 1.0;
  int Width = 800;
  int Height = 600;
  std::string OutputFile = "relief-render.png";
  bool SampleCount = false;
};

// The default depth scale, as a fraction of the mesh's bounding-box diagonal: deep
// enough to be seen on any mesh, shallow enough for a coarse mesh to carry it.
constexpr double DefaultDepthFraction = 0.02;

void PrintUsage(std::ostream& os)
{
  const Options defaults;
  os << "usage: relief render --mesh FILE --height FILE [options]\n"
        "Renders a mesh with a height map as relief (vtkOpenGLReliefMapper) into a PNG.\n"
        "\n"
        "  --mesh FILE          mesh to render: .vtp .vtk .ply .obj .stl (required)\n"
        "  --height FILE        height map, any image OpenImageIO reads; white = high\n"
        "                       (required)\n"
        "  --color FILE         colour texture, sampled at the relief hit (default: none)\n"
        "  --depth-scale D      world depth of the deepest level (default: "
     << 100.0 * DefaultDepthFraction
     << "% of the\n"
        "                       mesh's bounding-box diagonal)\n"
        "  --tiles N | UxV      multiply the texture coordinates by N, or u by U and v\n"
        "                       by V (default: "
     << defaults.Tiles[0]
     << ")\n"
        "  --texture-map plane|cylinder|sphere\n"
        "                       generate texture coordinates for a mesh that has none\n"
        "                       (default: use the mesh's own)\n"
        "  --depth-convention   read the height map as white = deep\n"
        "  --search automatic|linear|linear-binary|secant|exact-dda|safety-radius|\n"
        "           cone-step|maximum-mipmap|robust-binary|slope-mipmap\n"
        "                       ray search method (default: automatic)\n"
        "  --screen-tolerance P pixels the automatic search may leave out, 0 to 100\n"
        "                       (default: 0.5; 0: exact everywhere)\n"
        "  --automatic-acceleration cone-step|slope-mipmap\n"
        "                       what the automatic search steps long runs over\n"
        "                       (default: cone-step; slope-mipmap: fewer samples, more memory)\n"
        "  --linear-steps N     linear search steps, 1 to 512 (default: "
     << defaults.LinearSteps
     << ")\n"
        "  --binary-steps N     binary refinement steps, 0 to 32 (default: "
     << defaults.BinarySteps
     << ")\n"
        "  --safety-tolerance E depth the safety-radius search may pass below the\n"
        "                       surface unnoticed, 0 or more (default: 0, exact)\n"
        "  --no-shadows         turn self-shadowing off\n"
        "  --point-shading      light each pixel by the normal at its hit alone, not over\n"
        "                       its footprint (faster where minified; aliases there)\n"
        "  --quadric            curved relief (vtkOpenGLQuadricReliefMapper): the relief\n"
        "                       carves the outline of a curved mesh\n"
        "  --derivative         tangent-free relief (vtkOpenGLDerivativeReliefMapper):\n"
        "                       the frame from screen-space derivatives; flat shading\n"
        "                       on a mesh without normals\n"
        "  --azimuth A          degrees around the view up, from the reset camera (default: "
     << defaults.Azimuth
     << ")\n"
        "  --elevation E        degrees up, from the reset camera (default: "
     << defaults.Elevation
     << ")\n"
        "  --zoom Z             zoom factor, from the reset camera (default: "
     << defaults.Zoom
     << ")\n"
        "  --size WxH           image size in pixels (default: "
     << defaults.Width << "x" << defaults.Height
     << ")\n"
        "  --output FILE        PNG to write (default: "
     << defaults.OutputFile
     << ")\n"
        "  --sample-count       render the height samples per pixel instead of shading:\n"
        "                       red = min(255, samples) / 255 on a black background\n"
        "  --help               print this help and exit\n";
}

bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(value);
}

bool ParseInteger(const std::string& text, int& value)
{
  char* end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || parsed < VTK_INT_MIN || parsed > VTK_INT_MAX)
  {
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

bool ParseSize(const std::string& text, int& width, int& height)
{
  const std::string::size_type x = text.find('x');
  return x != std::string::npos && ParseInteger(text.substr(0, x), width) &&
    ParseInteger(text.substr(x + 1), height) && width > 0 && height > 0;
}

enum class ParseResult
{
  Run,
  Help,
  Failed
};

// GNU-style long options: `--name value` or `--name=value`.
ParseResult ParseArguments(int argc, char* argv[], Options& options, std::string& error)
{
  using Setter = std::function<bool(const std::string&)>;
  auto positive = [](double& target) {
    return [&target](const std::string& text) { return ParseNumber(text, target) && target > 0.0; };
  };
  auto number = [](double& target) {
    return [&target](const std::string& text) { return ParseNumber(text, target); };
  };
  auto integerIn = [](int& target, int low, int high) {
    return [&target, low, high](const std::string& text) {
      return ParseInteger(text, target) && target >= low && target <= high;
    };
  };
  auto text = [](std::string& target) {
    return [&target](const std::string& value) {
      target = value;
      return !value.empty();
    };
  };
  const std::map<std::string, Setter> valueOptions = {
    { "--mesh", text(options.MeshFile) },
    { "--height", text(options.HeightFile) },
    { "--color", text(options.ColorFile) },
    { "--depth-scale",
      [&options, positive](const std::string& value) {
        return positive(options.DepthScale.emplace())(value);
      } },
    { "--tiles",
      [&options, positive](const std::string& value) {
        const std::string::size_type x = value.find('x');
        if (x == std::string::npos)
        {
          return positive(options.Tiles[0])(value) && positive(options.Tiles[1])(value);
        }
        return positive(options.Tiles[0])(value.substr(0, x)) &&
          positive(options.Tiles[1])(value.substr(x + 1));
      } },
    { "--texture-map",
      [&options](const std::string& value) {
        options.TextureMap = value;
        return value == "plane" || value == "cylinder" || value == "sphere";
      } },
    { "--search",
      [&options](const std::string& value) {
        options.SearchMethod = ReliefScene::SearchMethodNamed(value);
        return options.SearchMethod >= 0;
      } },
    { "--screen-tolerance",
      [&options](const std::string& value) {
        return ParseNumber(value, options.ScreenTolerance) && options.ScreenTolerance >= 0.0 &&
          options.ScreenTolerance <= 100.0;
      } },
    { "--automatic-acceleration",
      [&options](const std::string& value) {
        options.AutomaticAcceleration = ReliefScene::SearchMethodNamed(value);
        return options.AutomaticAcceleration == vtkOpenGLReliefMapper::CONE_STEP ||
          options.AutomaticAcceleration == vtkOpenGLReliefMapper::SLOPE_MIPMAP;
      } },
    { "--linear-steps", integerIn(options.LinearSteps, 1, 512) },
    { "--binary-steps", integerIn(options.BinarySteps, 0, 32) },
    { "--safety-tolerance",
      [&options](const std::string& value) {
        return ParseNumber(value, options.SafetyTolerance) && options.SafetyTolerance >= 0.0;
      } },
    { "--azimuth", number(options.Azimuth) },
    { "--elevation", number(options.Elevation) },
    { "--zoom", positive(options.Zoom) },
    { "--size",
      [&options](const std::string& value) {
        return ParseSize(value, options.Width, options.Height);
      } },
    { "--output", text(options.OutputFile) },
  };
  const std::map<std::string, std::function<void()>> flags = {
    { "--depth-convention", [&options]() { options.DepthConvention = true; } },
    { "--no-shadows", [&options]() { options.Shadows = false; } },
    { "--point-shading", [&options]() { options.FootprintShading = false; } },
    { "--quadric", [&options]() { options.Quadric = true; } },
    { "--derivative", [&options]() { options.Derivative = true; } },
    { "--sample-count", [&options]() { options.SampleCount = true; } },
  };

  for (int i = 1; i < argc; ++i)
  {
    std::string name = argv[i];
    std::optional<std::string> value;
    const std::string::size_type equals = name.find('=');
    if (name.rfind("--", 0) == 0 && equals != std::string::npos)
    {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
    }
    if (name == "--help" || name == "-h")
    {
      return ParseResult::Help;
    }
    const auto flag = flags.find(name);
    if (flag != flags.end())
    {
      if (value)
      {
        error = name + " takes no value";
        return ParseResult::Failed;
      }
      flag->second();
      continue;
    }
    const auto option = valueOptions.find(name);
    if (option == valueOptions.end())
    {
      error = "unknown option '" + name + "'";
      return ParseResult::Failed;
    }
    if (!value)
    {
      if (i + 1 == argc)
      {
        error = name + " needs a value";
        return ParseResult::Failed;
      }
      value = argv[++i];
    }
    if (!option->second(*value))
    {
      error = "bad value '" + *value + "' for " + name + " (see --help)";
      return ParseResult::Failed;
    }
  }
  if (options.MeshFile.empty() || options.HeightFile.empty())
  {
    error = "--mesh and --height are required";
    return ParseResult::Failed;
  }
  if (options.Quadric && options.Derivative)
  {
    error = "--quadric and --derivative are two frames: choose one";
    return ParseResult::Failed;
  }
  return ParseResult::Run;
}

bool IsReadableFile(const std::string& fileName, const std::string& role, std::string& error)
{
  if (!vtksys::SystemTools::FileExists(fileName, true))
  {
    error = role + " '" + fileName + "' does not exist or is not a file";
    return false;
  }
  if (!vtksys::SystemTools::TestFileAccess(fileName, vtksys::TEST_FILE_READ))
  {
    error = role + " '" + fileName + "' is not readable";
    return false;
  }
  return true;
}

// Checked before rendering, so that a typo in --output does not cost a render.
bool IsWritableFolderOf(const std::string& fileName, std::string& error)
{
  const std::string folder = vtksys::SystemTools::GetFilenamePath(fileName);
  if (!folder.empty() && !vtksys::SystemTools::FileIsDirectory(folder))
  {
    error = "cannot write '" + fileName + "': folder '" + folder + "' does not exist";
    return false;
  }
  return true;
}

vtkSmartPointer<vtkImageData> ReadImage(
  const std::string& fileName, const std::string& role, std::string& error)
{
  vtkNew<vtkOpenImageIOReader> reader;
  if (!reader->CanReadFile(fileName.c_str()))
  {
    error = role + " '" + fileName + "' is not an image OpenImageIO can read";
    return nullptr;
  }
  reader->SetFileName(fileName.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (image->GetNumberOfPoints() == 0)
  {
    error = "could not read " + role + " '" + fileName + "'";
    return nullptr;
  }
  return image;
}

// vtkOpenImageIOReader keeps the file's bit depth, while vtkTexture takes only
// unsigned char as colour: rescale 16-bit and float pictures to 8 bits.
vtkSmartPointer<vtkTexture> ColorTexture(vtkImageData* image)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  if (image->GetScalarType() == VTK_UNSIGNED_CHAR)
  {
    texture->SetInputData(image);
  }
  else
  {
    vtkNew<vtkImageShiftScale> eightBits;
    eightBits->SetInputData(image);
    const bool floating =
      image->GetScalarType() == VTK_FLOAT || image->GetScalarType() == VTK_DOUBLE;
    eightBits->SetScale(floating ? 255.0 : 255.0 / image->GetScalarTypeMax());
    eightBits->SetOutputScalarTypeToUnsignedChar();
    eightBits->ClampOverflowOn();
    texture->SetInputConnection(eightBits->GetOutputPort());
  }
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->RepeatOn();
  return texture;
}

vtkSmartPointer<vtkPolyData> MapTextureCoordinates(vtkPolyData* mesh, const std::string& kind)
{
  vtkSmartPointer<vtkDataSetAlgorithm> map;
  if (kind == "plane")
  {
    map = vtkSmartPointer<vtkTextureMapToPlane>::New();
  }
  else if (kind == "cylinder")
  {
    map = vtkSmartPointer<vtkTextureMapToCylinder>::New();
  }
  else
  {
    map = vtkSmartPointer<vtkTextureMapToSphere>::New();
  }
  map->SetInputData(mesh);
  map->Update();
  return map->GetPolyDataOutput();
}

// A directional scene light from the upper left of the camera's view, in front of the
// focal point: the light of the project's test scene, (-1, 1, 1) seen from +z.
vtkSmartPointer<vtkLight> UpperLeftLight(vtkCamera* camera)
{
  double forward[3];
  double up[3];
  double right[3];
  camera->GetDirectionOfProjection(forward);
  camera->GetViewUp(up);
  vtkMath::Cross(forward, up, right);
  const double* focalPoint = camera->GetFocalPoint();
  double position[3];
  for (int i = 0; i < 3; ++i)
  {
    position[i] = focalPoint[i] + camera->GetDistance() * (up[i] - right[i] - forward[i]);
  }
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(position);
  light->SetFocalPoint(camera->GetFocalPoint());
  return light;
}

double RenderMilliseconds(vtkRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

// Mean and largest height-sample count over the pixels the relief covers (red > 0).
void PrintSampleCounts(vtkImageData* image)
{
  vtkUnsignedCharArray* pixels =
    vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  double total = 0.0;
  int largest = 0;
  vtkIdType covered = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    const int samples = pixels->GetValue(i * pixels->GetNumberOfComponents());
    if (samples > 0)
    {
      total += samples;
      largest = std::max(largest, samples);
      ++covered;
    }
  }
  std::cout << "height samples per covered pixel: mean "
            << (covered > 0 ? total / covered : 0.0) << ", max " << largest << " over "
            << covered << " pixels\n";
}
}

int main(int argc, char* argv[])
{
  Options options;
  std::string error;
  switch (ParseArguments(argc, argv, options, error))
  {
    case ParseResult::Help:
      PrintUsage(std::cout);
      return EXIT_SUCCESS;
    case ParseResult::Failed:
      std::cerr << "relief render: " << error << "\nTry 'relief render --help'.\n";
      return UsageFailure;
    case ParseResult::Run:
      break;
  }

  auto fail = [&error]() {
    std::cerr << "relief render: " << error << "\n";
    return RunFailure;
  };
  if (!IsReadableFile(options.MeshFile, "mesh", error) ||
    !IsReadableFile(options.HeightFile, "height map", error) ||
    (!options.ColorFile.empty() && !IsReadableFile(options.ColorFile, "colour texture", error)) ||
    !IsWritableFolderOf(options.OutputFile, error))
  {
    return fail();
  }
  vtkSmartPointer<vtkPolyData> mesh = ReliefScene::ReadMesh(options.MeshFile, error);
  if (!mesh)
  {
    return fail();
  }
  vtkSmartPointer<vtkImageData> heightMap = ReadImage(options.HeightFile, "height map", error);
  if (!heightMap)
  {
    return fail();
  }
  vtkSmartPointer<vtkImageData> colorImage;
  if (!options.ColorFile.empty())
  {
    colorImage = ReadImage(options.ColorFile, "colour texture", error);
    if (!colorImage)
    {
      return fail();
    }
  }

  if (!mesh->GetPointData()->GetTCoords())
  {
    if (options.TextureMap.empty())
    {
      std::cerr << "relief render: the mesh has no texture coordinates; pass --texture-map "
                   "plane|cylinder|sphere to generate some.\n";
    }
    else
    {
      mesh = MapTextureCoordinates(mesh, options.TextureMap);
    }
  }
  else if (!options.TextureMap.empty())
  {
    std::cerr << "relief render: the mesh has its own texture coordinates; --texture-map "
              << options.TextureMap << " is not applied.\n";
  }
  if ((options.Tiles[0] != 1.0 || options.Tiles[1] != 1.0) && mesh->GetPointData()->GetTCoords())
  {
    ReliefScene::TileTextureCoordinates(mesh, options.Tiles[0], options.Tiles[1]);
  }

  vtkSmartPointer<vtkOpenGLReliefMapper> mapper;
  if (options.Quadric)
  {
    mapper = vtkSmartPointer<vtkOpenGLQuadricReliefMapper>::New();
  }
  else if (options.Derivative)
  {
    mapper = vtkSmartPointer<vtkOpenGLDerivativeReliefMapper>::New();
  }
  else
  {
    mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  }
  mapper->SetInputData(mesh);
  mapper->SetHeightMapData(heightMap);
  mapper->SetDepthScale(options.DepthScale.value_or(DefaultDepthFraction * mesh->GetLength()));
  if (options.DepthConvention)
  {
    mapper->GetReliefTextureFilter()->SetInputConventionToDepth();
  }
  mapper->SetSearchMethod(options.SearchMethod);
  mapper->SetScreenTolerance(options.ScreenTolerance);
  mapper->SetAutomaticAcceleration(options.AutomaticAcceleration);
  mapper->SetLinearSteps(options.LinearSteps);
  mapper->SetBinarySteps(options.BinarySteps);
  mapper->SetSafetyRadiusTolerance(options.SafetyTolerance);
  mapper->SetSelfShadowing(options.Shadows);
  mapper->SetFootprintShading(options.FootprintShading);
  if (options.SampleCount)
  {
    mapper->SetDisplayModeToSampleCount();
  }

  auto actor = ReliefScene::ReliefActor(mapper, std::string());
  if (colorImage)
  {
    actor->SetTexture(ColorTexture(colorImage));
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  // Black behind a sample-count image, so that only covered pixels have red.
  if (options.SampleCount)
  {
    renderer->SetBackground(0.0, 0.0, 0.0);
  }
  renderer->AddActor(actor);
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  // The scene's light is placed for a camera looking down -z, as the reset camera does.
  // It turns with the azimuth, so that every side the camera goes round to is lit, but
  // not with the elevation: as in the test scenes, a camera raised above a surface
  // looks down on it lit from the front, where a light raised with the camera would
  // graze it.
  camera->Azimuth(options.Azimuth);
  renderer->RemoveAllLights();
  renderer->AddLight(UpperLeftLight(camera));
  camera->Elevation(options.Elevation);
  camera->OrthogonalizeViewUp();
  camera->Zoom(options.Zoom);
  renderer->ResetCameraClippingRange();

  // The first frame also builds the shaders and uploads the textures; the median of
  // the next ones is what every further frame of this view costs.
  const double firstMilliseconds = RenderMilliseconds(window);
  constexpr int TimedFrames = 5;
  const double frameMilliseconds = ReliefScene::MedianFrameMilliseconds(window, 0, TimedFrames);

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ShouldRerenderOff();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(options.OutputFile.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error = "could not write '" + options.OutputFile + "'";
    return fail();
  }

  std::cout << options.OutputFile << "  " << options.Width << "x" << options.Height << "  render "
            << frameMilliseconds << " ms (median of " << TimedFrames
            << " frames; first frame, with shader build and uploads: "
            << firstMilliseconds << " ms)\n";
  if (options.SampleCount)
  {
    PrintSampleCounts(grab->GetOutput());
  }
  return EXIT_SUCCESS;
}

#include "ReliefImpostorStudy.h"

#include "ReliefChart.h"
#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefImpostorMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkReliefImpostorFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace
{
constexpr double ObjectSize = 2.0; // the object's box, about: depth errors are shares of it

// The mesh, its impostor and its box, each a mapper the field's actors take in turn.
struct Mappers
{
  vtkNew<vtkPolyDataMapper> Mesh;
  vtkNew<vtkOpenGLReliefImpostorMapper> Impostor;
  vtkNew<vtkPolyDataMapper> Box;
};

void Use(vtkRenderer* renderer, vtkMapper* mapper)
{
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
  {
    if (auto* actor = vtkActor::SafeDownCast(prop))
    {
      actor->SetMapper(mapper);
    }
  }
}

// AutomaticResolution from its least again: each scene's textures are what it needs, not
// what an earlier scene or the calibration's nearer views needed.
void RestartAutomaticResolution(vtkOpenGLReliefImpostorMapper* impostor)
{
  impostor->SetAutomaticResolution(false);
  impostor->SetAutomaticResolution(true);
}

double CoveredShare(const ReliefMetrics::Capture& capture)
{
  long covered = 0;
  for (size_t pixel = 0; pixel < capture.EyeDepth.size(); ++pixel)
  {
    covered += capture.Covers(pixel) ? 1 : 0;
  }
  return static_cast<double>(covered) / std::max<size_t>(capture.EyeDepth.size(), 1);
}

// The camera distance (in field half widths) at which the field covers `share` of the
// window, found on the impostor, which draws it fast; never nearer than `nearest`, where
// a field of several instances still shows whole (nearer, the view falls between them
// and what it covers no longer shrinks with distance).
double Calibrate(
  vtkRenderWindow* window, vtkRenderer* renderer, double half, double share, double nearest)
{
  double near = nearest;
  double far = 60.0;
  for (int step = 0; step < 10; ++step)
  {
    const double distance = std::sqrt(near * far);
    ReliefScene::ViewField(renderer, half, distance);
    window->Render();
    const double covered = CoveredShare(ReliefScene::Capture(window, renderer));
    (covered > share ? near : far) = distance;
  }
  return std::sqrt(near * far);
}

// Height samples per pixel the impostor covers, from its SampleCount display.
double SamplesPerPixel(vtkRenderWindow* window, vtkOpenGLReliefImpostorMapper* impostor)
{
  impostor->SetDisplayModeToSampleCount();
  window->Render();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  impostor->SetDisplayModeToShaded();
  double sum = 0.0;
  long covered = 0;
  for (size_t k = 0; k + 2 < pixels.size(); k += 3)
  {
    // the display writes red alone; the background holds blue
    if (pixels[k] > 0 && pixels[k + 2] == 0)
    {
      sum += pixels[k];
      ++covered;
    }
  }
  return covered ? sum / covered : 0.0;
}

struct Row
{
  std::string Name;
  int Instances = 0;
  double Share = 0.0; // of the window the mesh covers
  double MeshMilliseconds = 0.0;
  double ImpostorMilliseconds = 0.0;
  double Silhouette = 0.0;
  double Depth = 0.0; // median, a share of the object's size
  double Colour = 0.0;
  double ColourSupersampled = 0.0; // against the mesh supersampled 3x3
  double MeshColourSupersampled = 0.0; // the mesh's own, at one sample a pixel
  double Samples = 0.0;
  long long Bytes = 0;
  int DepthResolution = 0; // the capture's, as the impostor was drawn
};

// The mesh and the impostor in the renderer's current view: times and errors.
Row Measure(vtkRenderWindow* window, vtkRenderer* renderer, Mappers& mappers, int frames,
  int meshFrames)
{
  Row row;
  Use(renderer, mappers.Mesh);
  row.MeshMilliseconds = ReliefScene::MedianFrameMilliseconds(window, 1, meshFrames);
  const ReliefMetrics::Capture truth = ReliefScene::Capture(window, renderer);
  // what an antialiased camera sees of the mesh
  constexpr int Supersampling = 3;
  const int width = window->GetSize()[0];
  const int height = window->GetSize()[1];
  window->SetSize(Supersampling * width, Supersampling * height);
  window->Render();
  const ReliefMetrics::Capture supersampled =
    ReliefMetrics::Downsample(ReliefScene::Capture(window, renderer), Supersampling);
  window->SetSize(width, height);
  Use(renderer, mappers.Box);
  window->Render();
  const ReliefMetrics::Capture boxes = ReliefScene::Capture(window, renderer);
  Use(renderer, mappers.Impostor);
  row.ImpostorMilliseconds = ReliefScene::MedianFrameMilliseconds(window, 1, frames);
  const ReliefMetrics::Capture drawn = ReliefScene::Capture(window, renderer);
  row.Share = CoveredShare(truth);
  row.Silhouette = ReliefMetrics::SilhouetteError(drawn, boxes, truth);
  row.Depth = ReliefMetrics::MeasureDepthError(drawn, truth, ObjectSize).Median;
  row.Colour = ReliefMetrics::MeasureColourError(drawn, truth).Rmse;
  row.ColourSupersampled = ReliefMetrics::MeasureColourError(drawn, supersampled).Rmse;
  row.MeshColourSupersampled = ReliefMetrics::MeasureColourError(truth, supersampled).Rmse;
  row.Samples = SamplesPerPixel(window, mappers.Impostor);
  row.Bytes = mappers.Impostor->GetTextureBytes();
  row.DepthResolution = mappers.Impostor->GetImpostorFilter()->GetDepthResolution();
  return row;
}

// GPU bytes of the mesh as VTK's mapper holds it: positions, normals and colours per
// point, three indices per triangle.
long long MeshBytes(vtkPolyData* mesh)
{
  const long long perPoint = 12 + (mesh->GetPointData()->GetNormals() ? 12 : 0) +
    (mesh->GetPointData()->GetScalars() ? 4 : 0);
  return perPoint * mesh->GetNumberOfPoints() + 12LL * mesh->GetNumberOfPolys();
}

std::string Table(const std::vector<Row>& rows, long long meshBytes)
{
  std::ostringstream out;
  out << std::fixed;
  out << "| view | instances | window covered | mesh ms/frame | impostor ms/frame | speed-up | "
         "silhouette error | depth error (median) | colour RMSE | colour RMSE, mesh 3x3 "
         "(the mesh's own) | samples/pixel | depth texels | texture bytes (x mesh) |\n"
      << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
         "| ---: |\n";
  for (const Row& row : rows)
  {
    out << "| " << row.Name << " | " << row.Instances << " | " << std::setprecision(1)
        << 100.0 * row.Share << "% | " << std::setprecision(1) << row.MeshMilliseconds << " | "
        << row.ImpostorMilliseconds << " | " << std::setprecision(2)
        << row.MeshMilliseconds / std::max(row.ImpostorMilliseconds, 1e-9) << "x | "
        << std::setprecision(4) << row.Silhouette << " | " << row.Depth << " | " << row.Colour
        << " | " << row.ColourSupersampled << " (" << row.MeshColourSupersampled << ") | "
        << std::setprecision(1) << row.Samples << " | " << row.DepthResolution << "^2 | "
        << row.Bytes << " (" << std::setprecision(3)
        << static_cast<double>(row.Bytes) / std::max(meshBytes, 1LL) << ") |\n";
  }
  return out.str();
}
}

std::string ReliefImpostorStudy::Study(const Options& options)
{
  vtkSmartPointer<vtkPolyData> object = ReliefScene::ImpostorObject(options.MeshResolution);
  Mappers mappers;
  mappers.Mesh->SetInputData(object);
  mappers.Impostor->SetInputData(object);
  vtkNew<vtkCubeSource> box;
  box->SetBounds(mappers.Impostor->GetBounds());
  mappers.Box->SetInputConnection(box->GetOutputPort());
  const long long meshBytes = MeshBytes(object);
  constexpr double Spacing = 2.5;

  std::vector<Row> instanceRows;
  std::vector<Row> searchRows;
  std::vector<Row> screenRows;
  std::vector<ReliefChart::Series> costSeries;
  for (int instances : options.Instances)
  {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    vtkSmartPointer<vtkRenderer> renderer =
      ReliefScene::LitRenderer(window, options.Width, options.Height);
    const double half = ReliefScene::AddField(renderer, mappers.Impostor, instances, Spacing);
    const int meshFrames = instances >= 1000 ? options.SlowFrames : options.Frames;
    // the field covering a quarter of the window
    const double nearest = instances == 1 ? 1.3 : (instances < 100 ? 3.5 : 2.0);
    ReliefScene::ViewField(
      renderer, half, Calibrate(window, renderer, half, options.FieldShare, nearest));
    RestartAutomaticResolution(mappers.Impostor);
    Row row = Measure(window, renderer, mappers, options.Frames, meshFrames);
    row.Name = "a quarter of the window";
    row.Instances = instances;
    instanceRows.push_back(row);
    if (instances != 1)
    {
      continue; // the screen sweep is of one instance: a field shows whole only far off
    }
    ReliefChart::Series mesh{ "mesh, one instance" };
    ReliefChart::Series impostor{ "impostor, one instance" };
    mesh.Line = impostor.Line = true;
    for (double share : options.ScreenShares)
    {
      Use(renderer, mappers.Impostor);
      ReliefScene::ViewField(renderer, half, Calibrate(window, renderer, half, share, nearest));
      RestartAutomaticResolution(mappers.Impostor);
      Row screen = Measure(window, renderer, mappers, options.Frames, meshFrames);
      std::ostringstream name;
      name << std::setprecision(3) << share << " of the window";
      screen.Name = name.str();
      screen.Instances = instances;
      screenRows.push_back(screen);
      mesh.X.push_back(screen.Share);
      mesh.Y.push_back(screen.MeshMilliseconds);
      impostor.X.push_back(screen.Share);
      impostor.Y.push_back(screen.ImpostorMilliseconds);
    }
    costSeries.push_back(mesh);
    costSeries.push_back(impostor);
  }

  // error against texture resolution: one instance, a quarter of the window
  std::ostringstream resolutionTable;
  resolutionTable << std::fixed
                  << "| depth texels | colour texels | silhouette error | depth error (median) "
                     "| colour RMSE | impostor ms/frame | texture bytes | x mesh bytes |\n"
                  << "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  ReliefChart::Series silhouettes{ "silhouette error" };
  ReliefChart::Series depths{ "depth error (median, of the object's size)" };
  ReliefChart::Series colours{ "colour RMSE" };
  {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    vtkSmartPointer<vtkRenderer> renderer =
      ReliefScene::LitRenderer(window, options.Width, options.Height);
    const double half = ReliefScene::AddField(renderer, mappers.Impostor, 1, Spacing);
    ReliefScene::ViewField(
      renderer, half, Calibrate(window, renderer, half, options.FieldShare, 1.3));
    mappers.Impostor->AutomaticResolutionOff();
    for (int resolution : options.DepthResolutions)
    {
      mappers.Impostor->GetImpostorFilter()->SetDepthResolution(resolution);
      mappers.Impostor->GetImpostorFilter()->SetColourResolution(std::min(2 * resolution, 2048));
      const Row row = Measure(window, renderer, mappers, options.Frames, options.Frames);
      resolutionTable << "| " << resolution << "^2 | " << std::min(2 * resolution, 2048)
                      << "^2 | " << std::setprecision(4) << row.Silhouette << " | " << row.Depth
                      << " | " << row.Colour << " | " << std::setprecision(1)
                      << row.ImpostorMilliseconds << " | " << row.Bytes << " | "
                      << std::setprecision(2) << static_cast<double>(row.Bytes) / meshBytes
                      << " |\n";
      for (auto* series : { &silhouettes, &depths, &colours })
      {
        series->X.push_back(resolution);
        series->Line = true;
      }
      silhouettes.Y.push_back(std::max(row.Silhouette, ReliefChart::LogFloor));
      depths.Y.push_back(std::max(row.Depth, ReliefChart::LogFloor));
      colours.Y.push_back(std::max(row.Colour, ReliefChart::LogFloor));
    }
    // colours held uncompressed, at the resolution the view asks for
    RestartAutomaticResolution(mappers.Impostor);
    mappers.Impostor->SetCompressColours(false);
    const Row uncompressed = Measure(window, renderer, mappers, options.Frames, options.Frames);
    mappers.Impostor->SetCompressColours(true);
    const Row compressed = Measure(window, renderer, mappers, options.Frames, options.Frames);
    for (const Row* row : { &compressed, &uncompressed })
    {
      resolutionTable << "| " << row->DepthResolution << "^2 (automatic) | "
                      << 2 * row->DepthResolution << "^2, "
                      << (row == &compressed ? "compressed (default)" : "uncompressed") << " | "
                      << std::setprecision(4) << row->Silhouette << " | " << row->Depth << " | "
                      << row->Colour << " | " << std::setprecision(1)
                      << row->ImpostorMilliseconds << " | " << row->Bytes << " | "
                      << std::setprecision(2) << static_cast<double>(row->Bytes) / meshBytes
                      << " |\n";
    }

    // the searches, in the same view at the defaults
    const std::pair<const char*, int> searches[] = {
      { "MaximumMipmap (Automatic, the default)", vtkOpenGLReliefMapper::MAXIMUM_MIPMAP },
      { "ExactDDA", vtkOpenGLReliefMapper::EXACT_DDA },
      { "LinearBinary 64+8", vtkOpenGLReliefMapper::LINEAR_BINARY },
    };
    for (const auto& search : searches)
    {
      mappers.Impostor->SetSearchMethod(search.second);
      Row row = Measure(window, renderer, mappers, options.Frames, options.Frames);
      row.Name = search.first;
      row.Instances = 1;
      searchRows.push_back(row);
    }
    mappers.Impostor->SetSearchMethod(vtkOpenGLReliefMapper::AUTOMATIC);
  }

  std::ostringstream out;
  out << std::fixed;
  out << "ImpostorObject at resolution " << options.MeshResolution << ": "
      << object->GetNumberOfPolys() << " triangles, " << object->GetNumberOfPoints()
      << " points, " << meshBytes << " bytes of vertex and index buffers. The impostor: "
      << "vtkOpenGLReliefImpostorMapper at its defaults (six orthographic views; "
         "AutomaticResolution: depth texels per view side the power of two at or above the "
         "pixels the box spans, 64^2 to 512^2, colour twice that; colours compressed (DXT1), "
         "normals octahedral in two bytes; MaximumMipmap), its resolution started again from "
         "the least for each scene. "
      << options.Width << "x" << options.Height
      << ", one scene light, instances on a grid sharing one mapper, looked at from 40 "
         "degrees above; ms/frame are medians of "
      << options.Frames << " frames (" << options.SlowFrames
      << " for 1000 meshes) after one warm-up. Errors are against the mesh drawn by VTK's "
         "mapper in the same view: silhouette error against the boxes' (1 is no better "
         "than drawing the boxes), depth as a share of the object's size, colour RMSE over "
         "the window, also against the mesh supersampled 3x3 (what an antialiased camera "
         "sees), beside the mesh's own error against it.\n\n"
      << "The impostor's textures, made once for all instances: "
      << instanceRows.back().Bytes << " bytes for " << instanceRows.back().Instances
      << " instances over a quarter of the window (" << std::setprecision(3)
      << static_cast<double>(instanceRows.back().Bytes) / meshBytes
      << " times the mesh's buffers), " << instanceRows.front().Bytes << " for "
      << instanceRows.front().Instances << " (" << std::setprecision(3)
      << static_cast<double>(instanceRows.front().Bytes) / meshBytes << " times).\n\n"
      << "### Instances\n\n"
      << Table(instanceRows, meshBytes) << "\n### Cost against screen size\n\n"
      << Table(screenRows, meshBytes)
      << "\n### Search methods\n\nOne instance covering a quarter of the window.\n\n"
      << Table(searchRows, meshBytes)
      << "\n### Error against texture resolution\n\nOne instance covering a quarter of the "
         "window; depth texels per view side, colour twice as many, compressed unless said; the "
         "last two rows: the resolution the view asks for, with and without compressed "
         "colours.\n\n"
      << resolutionTable.str();
  if (!options.ImageDirectory.empty())
  {
    ReliefChart::Axes cost;
    cost.Title = "Impostor against mesh: cost against screen size";
    cost.X = "share of the window covered";
    cost.Y = "ms/frame";
    cost.LogX = cost.LogY = true;
    ReliefChart::Write(costSeries, cost, options.ImageDirectory + "/impostor_cost.png");
    ReliefChart::Axes error;
    error.Title = "Impostor error against texture resolution";
    error.X = "depth texels per view side";
    error.Y = "error";
    error.LogX = error.LogY = true;
    ReliefChart::Write(
      { silhouettes, depths, colours }, error, options.ImageDirectory + "/impostor_error.png");
    out << "\n![cost against screen size](images/impostor_cost.png)\n\n"
        << "![error against texture resolution](images/impostor_error.png)\n";
  }
  return out.str();
}

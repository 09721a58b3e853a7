// Relief impostors against the mesh they replace (Baboud and Decoret 2006, s4; issue 19):
// ReliefScene::ImpostorObject at about 200k triangles, drawn by VTK's stock mapper and by
// vtkOpenGLReliefImpostorMapper (six orthographic views, MaximumMipmap), 1, 100 and
// 1000 instances sharing one mapper. For each: ms/frame of both in one run, the
// impostor's silhouette error (against its boxes'), depth error and colour RMSE against
// the mesh, its samples per pixel and bytes against the mesh's buffers; cost against
// screen size (where the impostor starts to win) and error against texture resolution,
// each with a chart.
#ifndef ReliefImpostorStudy_h
#define ReliefImpostorStudy_h

#include <string>
#include <vector>

namespace ReliefImpostorStudy
{
struct Options
{
  int Width = 800;
  int Height = 600;
  int MeshResolution = 320; ///< ImpostorObject's: about 2 x 320^2 triangles
  std::vector<int> Instances = { 1, 100, 1000 };
  /// the field's share of the window for the instance table (a quarter)
  double FieldShare = 0.25;
  /// shares of the window one instance covers in the screen-size sweep
  std::vector<double> ScreenShares = { 1.0, 0.25, 1.0 / 16.0, 1.0 / 64.0 };
  std::vector<int> DepthResolutions = { 64, 128, 256, 512, 1024 }; ///< colour: twice
  int Frames = 3;     ///< timed frames per figure, after a warm-up frame
  int SlowFrames = 1; ///< for renders over a second a frame
  std::string ImageDirectory; ///< where the charts go (PNG); none when empty
};

/// Runs the study; returns its Markdown section (context, tables, charts).
std::string Study(const Options& options);
}

#endif

// The scenes of vtkRelief's demo, benchmark and regression tests: one window, one key
// light, the project's height maps and colour textures. A starting point to copy from.
#ifndef ReliefScene_h
#define ReliefScene_h

#include "ReliefMetrics.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkActor;
class vtkImageData;
class vtkMapper;
class vtkOpenGLReliefMapper;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkTexture;

namespace ReliefScene
{
/// Where the project's height maps and textures are (default: the source tree's Data/).
void SetDataDirectory(const std::string& directory);

/// A file of the data directory.
std::string DataFile(const std::string& name);

/// A height map of Data/, read with vtkOpenImageIOReader.
vtkSmartPointer<vtkImageData> ReadImage(const std::string& name);

/// A surface read with the VTK reader its extension calls for (.vtp .vtk .ply .obj .stl;
/// a legacy file of another dataset type is reduced to its outer surface), or nullptr
/// with `error` saying why (unreadable, no polygons).
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& fileName, std::string& error);

/// A colour texture of Data/, repeating, interpolated and mipmapped.
vtkSmartPointer<vtkTexture> ReadTexture(const std::string& name);

/// Multiplies the texture coordinates of `surface` by (uTiles, vTiles), in place.
void TileTextureCoordinates(vtkPolyData* surface, double uTiles, double vTiles);

/// A unit square in the xy plane with texture coordinates [0, tiles]^2 and +z normals.
vtkSmartPointer<vtkPolyData> Square(double tiles = 1.0);

/// A torus (toroidal superquadric, size 0.5, thickness 0.4, axis y), `resolution`
/// facets around its ring, texture coordinates tiled 6 x 2 for square texels.
vtkSmartPointer<vtkPolyData> Torus(int resolution);

/// A sphere of radius 0.5, `resolution` facets around, texture tiled 4 x 2.
vtkSmartPointer<vtkPolyData> Sphere(int resolution);

/// A cylinder of radius 0.4 around z, 3 high, `resolution` facets around a full turn,
/// the part `sweep` degrees around (less than 360: an open mesh with boundaries on
/// every side), texture tiled 4 x 5 over a full turn; no normals.
vtkSmartPointer<vtkPolyData> Cylinder(int resolution, double sweep = 360.0);

/// A relief mapper on `surface` with `heightMap` of Data/ and a depth scale.
vtkSmartPointer<vtkOpenGLReliefMapper> ReliefMapper(
  vtkPolyData* surface, const std::string& heightMap, double depthScale);

/// The relief as real geometry (vtkReliefDisplacementFilter): `surface` subdivided until
/// its edges span at most `edgeTexels` texels of `relief` (vtkReliefTextureFilter's
/// output), sunk by the bilinear depth x depthScale; up to 2^24 triangles.
vtkSmartPointer<vtkPolyData> DisplacedMesh(
  vtkPolyData* surface, vtkImageData* relief, double depthScale, double edgeTexels);

/// Stones on a curved `surface`: the stones height map at `depthScale`, searched with
/// LinearBinary 32+6 (curved relief runs far at grazing outlines).
void SetStones(vtkOpenGLReliefMapper* mapper, vtkPolyData* surface, double depthScale);

/// An actor with `mapper`, the colour texture of Data/ (none when empty) and a
/// slightly specular material.
vtkSmartPointer<vtkActor> ReliefActor(vtkMapper* mapper, const std::string& colorTexture);

/// A renderer lit by one white scene light from the upper left, in a window of the
/// given size.
vtkSmartPointer<vtkRenderer> LitRenderer(vtkRenderWindow* window, int width, int height);

/// Looks at the unit square `angle` degrees away from its normal (0 = head-on).
void ViewSquare(vtkRenderer* renderer, double angle);

/// The showcase scenes, each filling `window` (of the given size).
///@{
/// Bricks on a square with `tiles` x `tiles` repeats, seen `angle` degrees off its normal.
vtkSmartPointer<vtkOpenGLReliefMapper> ShowBricks(vtkRenderWindow* window, int width, int height,
  double angle, double tiles = 2.0, double depthScale = 0.04);
/// The search method named `name` (GetSearchMethodAsString's names, case and dashes
/// ignored: "exact-dda" is ExactDDA), or -1.
int SearchMethodNamed(const std::string& name);
/// A width x height one-component float height image, heightAt(i, j) at texel (i, j).
vtkSmartPointer<vtkImageData> HeightImage(
  int width, int height, const std::function<float(int, int)>& heightAt);
/// Thin features (Baboud and Decoret 2006, Fig. 11): a 64x64 height image (white = high) of walls
/// and spikes one texel wide rising from a low floor.
vtkSmartPointer<vtkImageData> ThinFeatures();
/// Thin features on a square seen `angle` degrees from its normal, searched by `method`.
vtkSmartPointer<vtkOpenGLReliefMapper> ShowThinFeatures(
  vtkRenderWindow* window, int width, int height, double angle, int method);
/// Every search method (vtkReliefSearchMethod), in order of id: from the cheapest to the
/// exact ones.
const std::vector<int>& SearchMethods();
/// Thin features under every search method (SearchMethods(), left to right), at 45
/// degrees (top) and 80 degrees (bottom).
void ShowSearchMethods(vtkRenderWindow* window, int width, int height);
/// Cobblestones on a coarse torus.
vtkSmartPointer<vtkOpenGLReliefMapper> ShowTorus(vtkRenderWindow* window, int width, int height);
/// Rivets under a low light, self-shadowing on (left half) and off (right half).
void ShowSelfShadowing(vtkRenderWindow* window, int width, int height);
/// A plain sphere sunk into bricks, depth correction on (left half) and off (right half).
void ShowInterpenetration(vtkRenderWindow* window, int width, int height);
/// Plain texture mapping (left half) beside relief mapping (right half) of the same bricks.
void ShowPlainBesideRelief(vtkRenderWindow* window, int width, int height);
/// Stones on a coarse torus, close on its outline: the flat frame (left) keeps the
/// polygons' silhouette, the quadric frame (right) lets the relief carve it.
void ShowQuadricSilhouettes(vtkRenderWindow* window, int width, int height);
/// Stones on `mesh` (a file of Data/, read as is: no tangents) drawn by
/// vtkOpenGLDerivativeReliefMapper, without the file's normals when `normals` is false
/// (the flat frame), in the viewport (left, 0, right, 1) of `window`.
vtkSmartPointer<vtkOpenGLReliefMapper> ShowDerivativeMesh(vtkRenderWindow* window, int width,
  int height, const std::string& mesh, bool normals, double left = 0.0, double right = 1.0);
/// Tangent-free relief: torus.obj with its normals (smooth frame, left), without them
/// (flat frame, middle), and icosahedron.ply (Tichenor's (2012) faceted crystal, right).
void ShowDerivativeFrames(vtkRenderWindow* window, int width, int height);
/// A spotlight 3 above the origin, pointing down, as the only light of `renderer`.
void AddSpotlight(vtkRenderer* renderer);
/// Renders `renderer` through VTK's shadow-map passes (baker, then shadows).
void UseShadowMaps(vtkRenderer* renderer);
/// A stone sphere over a plain floor under a spotlight, through VTK's shadow-map passes:
/// the flat frame (left) casts the polygons' disc, the quadric frame (right) the stones'.
void ShowQuadricShadows(vtkRenderWindow* window, int width, int height);
///@}

/// `image` resampled to size x size texels (vtkImageResize).
vtkSmartPointer<vtkImageData> ResizedImage(vtkImageData* image, int size);

/// The height map `name` of Data/ resampled to size x size texels (ResizedImage).
vtkSmartPointer<vtkImageData> ResizedHeightMap(const std::string& name, int size);

/// The actors one study compares, in one renderer (its other props removed), shown one
/// at a time.
class Lineup
{
public:
  Lineup(vtkRenderWindow* window, vtkRenderer* renderer,
    const std::vector<vtkSmartPointer<vtkActor>>& actors);
  /// Only `shown` visible.
  void Show(vtkActor* shown);
  /// Only `shown` visible, rendered, and the window captured.
  ReliefMetrics::Capture Capture(vtkActor* shown);
  /// The median ms per frame of each of `timed`, over `rounds` rounds that time each in
  /// turn for `frames` frames (after 2 warm-up frames), so that machine noise hits all
  /// alike.
  std::vector<double> InterleavedMilliseconds(
    const std::vector<vtkActor*>& timed, int rounds, int frames);

private:
  vtkRenderWindow* Window;
  vtkRenderer* Renderer;
  std::vector<vtkSmartPointer<vtkActor>> Actors;
};

/**
 * A detailed object to stand in for a scanned part: a sphere, a cube half sunk into it
 * and a ring around both, tilted (concave where the ring passes the sphere), with point
 * scalars of elevation along z; about 2 x resolution^2 triangles. The same object is
 * drawn by the stock mapper as the ground truth of its impostor.
 */
vtkSmartPointer<vtkPolyData> ImpostorObject(int resolution);

/// The actor of a mesh drawn by VTK's stock mapper, and of its relief impostor
/// (vtkOpenGLReliefImpostorMapper), both lit alike.
vtkSmartPointer<vtkActor> MeshActor(vtkPolyData* mesh);
vtkSmartPointer<vtkActor> ImpostorActor(vtkPolyData* mesh);

/**
 * `count` actors sharing `mapper` on a square grid `spacing` apart in the plane z = 0,
 * each turned about z by its own angle and tinted its own colour (the same each call).
 * Returns the grid's half width.
 */
double AddField(vtkRenderer* renderer, vtkMapper* mapper, int count, double spacing);

/// The camera looking down at 40 degrees on the middle of a field of half width `half`,
/// from `distance` half widths away.
void ViewField(vtkRenderer* renderer, double half, double distance);

/// ImpostorObject drawn by VTK's stock mapper (left) and as a relief impostor (right).
void ShowImpostorBesideMesh(vtkRenderWindow* window, int width, int height);

/// ImpostorObject over a floor under a spotlight, through the shadow-map passes: drawn
/// by VTK's stock mapper (left) and as a relief impostor (right).
void ShowImpostorShadows(vtkRenderWindow* window, int width, int height);

/// A field of `count` impostors of ImpostorObject sharing one mapper.
void ShowImpostorField(vtkRenderWindow* window, int width, int height, int count);

/// Wall-clock milliseconds of each of `frames` renders after `warmup` renders.
std::vector<double> FrameMilliseconds(vtkRenderWindow* window, int warmup, int frames);

/// The median of `values` (not empty).
double Median(std::vector<double> values);

/// Median wall-clock milliseconds of `frames` renders after `warmup` renders.
double MedianFrameMilliseconds(vtkRenderWindow* window, int warmup = 3, int frames = 20);

/// The window's pixels, RGB, bottom row first.
std::vector<unsigned char> Pixels(vtkRenderWindow* window);

/// Height samples per covered pixel, from `mapper`'s SampleCount display mode (the
/// display caps a pixel's count at 255); the mapper is left in Shaded mode.
struct SampleStatistics
{
  double Mean = 0.0;
  int Maximum = 0;
  double Coverage = 0.0; ///< covered fraction of the view
};
SampleStatistics SampleCounts(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkOpenGLReliefMapper* mapper);

/// The window's colours and eye depths (distance in front of `renderer`'s camera, from
/// the depth buffer and the camera's clipping range), after a render.
ReliefMetrics::Capture Capture(vtkRenderWindow* window, vtkRenderer* renderer);
}

#endif

// Shared set-up of the relief regression tests: one window, one key light, the
// project's height maps and colour textures.
#ifndef ReliefTestScene_h
#define ReliefTestScene_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkActor;
class vtkImageData;
class vtkOpenGLReliefMapper;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkTexture;

namespace ReliefTestScene
{
/// A file of the project's Data/ folder.
std::string DataFile(const std::string& name);

/// A height map of Data/, read with vtkOpenImageIOReader.
vtkSmartPointer<vtkImageData> ReadImage(const std::string& name);

/// A colour texture of Data/, repeating, interpolated and mipmapped.
vtkSmartPointer<vtkTexture> ReadTexture(const std::string& name);

/// Multiplies the texture coordinates of `surface` by (uTiles, vTiles), in place.
void TileTextureCoordinates(vtkPolyData* surface, double uTiles, double vTiles);

/// A unit square in the xy plane with texture coordinates [0, tiles]^2 and +z normals.
vtkSmartPointer<vtkPolyData> Square(double tiles = 1.0);

/// A torus (toroidal superquadric) with texture coordinates tiled for square texels.
vtkSmartPointer<vtkPolyData> Torus();

/// A relief mapper on `surface` with `heightMap` of Data/ and a depth scale.
vtkSmartPointer<vtkOpenGLReliefMapper> ReliefMapper(
  vtkPolyData* surface, const std::string& heightMap, double depthScale);

/// An actor with `mapper`, the colour texture of Data/ (none when empty) and a
/// slightly specular material.
vtkSmartPointer<vtkActor> ReliefActor(
  vtkOpenGLReliefMapper* mapper, const std::string& colorTexture);

/// A renderer lit by one white scene light from the upper left, in a window of the
/// given size.
vtkSmartPointer<vtkRenderer> LitRenderer(vtkRenderWindow* window, int width, int height);

/// Looks at the unit square `angle` degrees away from its normal (0 = head-on).
void ViewSquare(vtkRenderer* renderer, double angle);

/// The window's pixels, RGB, bottom row first.
std::vector<unsigned char> Pixels(vtkRenderWindow* window);
}

#endif

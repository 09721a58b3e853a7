// Path-feature scenes (the path-feature paper, seed 004) shared by the demo, the
// regression tests and the benchmark: profiles, a brick wall's mortar with a crack, a
// protruding weld bead, an overhanging dovetail slot and an engraved ring of quadratic
// arcs, on a square or a cylinder.
#ifndef ReliefPathScene_h
#define ReliefPathScene_h

#include "vtkSmartPointer.h"

class vtkOpenGLPathFeatureMapper;
class vtkOpenGLQuadricPathFeatureMapper;
class vtkPathFeatureTextureFilter;
class vtkPolyData;
class vtkRenderWindow;

namespace ReliefPathScene
{
/// The profiles of Profiles(), by index.
enum Profile
{
  ROUND = 0,    // a half circle, 1 deep
  VEE = 1,      // a V, 1 deep
  MORTAR = 2,   // a flat-bottomed joint, 0.35 deep
  BEAD = 3,     // a weld bead, protruding 0.5
  DOVETAIL = 4  // a slot wider below than at its opening, 0.8 deep
};
vtkSmartPointer<vtkPolyData> Profiles();

/// Adds the showcase's materials to `filter` (mortar, crack, bead) and returns the first.
int AddMaterials(vtkPathFeatureTextureFilter* filter);

/**
 * The showcase's paths in one texture tile: on its left half a wall of bricks, whose
 * joints end on the bed joints (intersected ends, priorities) and which a crack that
 * narrows to nothing crosses; on its right half a weld bead, a dovetail slot and an
 * engraved ring of quadratic arcs. Material indices from `firstMaterial`.
 */
vtkSmartPointer<vtkPolyData> ShowcasePaths(int firstMaterial);

/// A path-feature mapper of `surface` with the showcase's paths, profiles and materials.
vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowcaseMapper(vtkPolyData* surface, double depthScale);

/// The showcase on a unit square seen `angle` degrees from its normal.
vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowPathFeatures(
  vtkRenderWindow* window, int width, int height, double angle);

/// The showcase's right half close up and low: the bead, the dovetail's overhang, the ring.
vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowPathFeaturesCloseUp(
  vtkRenderWindow* window, int width, int height);

/**
 * Path features cut into a relief base (vtkReliefPathOnRelief.glsl): the brick wall of
 * bricks_height.png, coloured by bricks_color.png, which a saw cut crosses diagonally
 * (through the bricks, over the deeper mortar), a crack narrowing to nothing crosses, and
 * a steel rod (a protruding bead) spans, casting its shadow on the bricks; the square
 * seen `angle` degrees from its normal.
 */
vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowPathFeaturesOnRelief(
  vtkRenderWindow* window, int width, int height, double angle);

/**
 * A cylinder of radius 0.4 and height 1 whose texture coordinates are isotropic in the
 * world (u once around, v up to its height over its circumference), 48 x 8 quads.
 */
vtkSmartPointer<vtkPolyData> LabelCylinder();

/// "VTK" engraved with a V-bit in a frame with rounded (quadratic) corners, on u = 0.5.
vtkSmartPointer<vtkPolyData> LabelPaths();

/// The label on the cylinder, the side it is on turned to the camera, drawn by
/// vtkOpenGLQuadricPathFeatureMapper (the engraving follows the curved surface).
vtkSmartPointer<vtkOpenGLQuadricPathFeatureMapper> ShowEngravedCylinder(
  vtkRenderWindow* window, int width, int height);

/// Round grooves on LabelCylinder(): around it at v = 0.1, 0.2, 0.3, along it at
/// u = (k + 0.5) / 12 from v = 0.03 to 0.37.
vtkSmartPointer<vtkPolyData> CylinderGrooves();

/// The grooved cylinder on the tangent frame (left, vtkOpenGLPathFeatureMapper: the
/// polygons' outline) and on the quadric frame (right, vtkOpenGLQuadricPathFeatureMapper:
/// the grooves notch the outline), a groove along it on each outline; `depthScale` the
/// grooves' depth in the world.
void ShowCurvedPathFeatures(vtkRenderWindow* window, int width, int height, double depthScale);
}

#endif

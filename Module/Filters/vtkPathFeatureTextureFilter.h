/**
 * @class   vtkPathFeatureTextureFilter
 * @brief   the grid and data textures of path-based surface detail: grooves, engravings,
 *          cracks and ridges as vectors in texture space
 *
 * Path-based surface detail (the path-feature paper, seed 004: paths of linear and
 * quadratic segments in texture space, each swept by a profile, s4.1) is drawn by
 * vtkOpenGLPathFeatureMapper from two textures this filter builds (s4.2-4.3): a grid over
 * one texture tile whose cells list the feature elements that reach into them, and a
 * data texture holding the elements, their paths' attributes, the profiles and the
 * materials.
 *
 * Input port 0, the paths: a vtkPolyData whose lines are the paths, their points' (x, y)
 * the texture coordinates (u, v) (z is ignored). A point flagged in the optional point
 * array "ControlPoint" (nonzero) is the control point of a quadratic segment between its
 * neighbours; two control points in a row imply an on-curve point half way between them,
 * as TrueType outlines do. Optional cell data, per path (defaults in brackets):
 * - "Width": the feature's full width, in texture units [DefaultWidth];
 * - "Profile": the index of its cross-section among the profiles [0];
 * - "Material": the index of its material (AddMaterial()), -1 for the actor's property [-1];
 * - "Priority": where features of different priorities overlap, the highest decides
 *   alone (a ridge of higher priority bridges a groove) [0];
 * - "Perturbation" (2 components): the scale of the profile, width and depth alike, at
 *   the path's start and at its end, varying linearly along its length: (1, 0) is a crack
 *   that narrows to nothing (s5.5) [(1, 1)].
 * Paths may leave [0, 1]: the texture tiles, and so do the features.
 *
 * Input port 1 (optional), the profiles: a vtkPolyData of one polyline per profile, a
 * point's x across the path in units of half the width (-1 on the path's left, +1 on its
 * right), its y the depth below the base surface in units of relief depth (the mapper's
 * DepthScale): positive cuts in, negative protrudes. The profile with the segment from its
 * last point back to its first encloses the feature: what it encloses below the base is
 * removed, what it encloses above is added, and the opening of a cut extends up through
 * every feature above it of no higher priority (s5.3). Profiles may overhang (x going
 * back, Fig. 8). Without port 1, profile 0 is a round-bottomed groove of depth 1.
 *
 * The base surface lies BaseDepth below the mesh, the most any feature protrudes, so that
 * protrusions reach up to the polygons and no deeper than MaximumDepth anything is cut.
 *
 * Output 0, the grid: a GridResolution[0] x GridResolution[1] image, 4 float components
 * ("PathFeatureGrid") per cell: the data texel of its list of elements, their number, the
 * least depth any of them reaches (the cell's top, which lets a ray above it skip the
 * cell: Algorithm 1), and its kind: 0 holds no feature, 1 one path's elements away from
 * their ends, 2 crossings, self-crossings and ends (CSG and more samples there).
 * Output 1, the data: an image DataWidth texels wide, 4 float components
 * ("PathFeatureData"), read as one array of texels:
 * - texel 0: (BaseDepth, MaximumDepth, grid width, grid height);
 * - a profile: (point count, the most |x|, the least y, the most y), then its points,
 *   two per texel (x0, y0, x1, y1);
 * - a material: (r, g, b, specular), (specular power, 0, 0, 0);
 * - a path: (half width, profile texel, material texel or -1, priority),
 *   (scale at start, scale at end, length, 1 where the profile is not centred: at some
 *   depth it holds other than one interval centred on x = 0, so that its revolved ends
 *   change across the plane through the element's axis; else 0);
 * - an element, a straight piece of a path: (start, end), (path texel, arc length along
 *   the path at its start, at its end, joins: 1 where the path's previous element goes
 *   on from its start, + 2 where the next goes on from its end, SmoothJointDegrees;
 *   + 4 and + 8 where its start, its end is not revolved: its neighbour goes on exactly
 *   (ExactJointRadians), or, where the path turns, the neighbour's revolved end holds all
 *   it would (a profile that holds one interval centred on x = 0 at every depth, that cuts
 *   or adds but not both, on a path of one scale: then only one of the two is revolved);
 *   a quadratic segment is stored as pieces whose chords stray at most 1/50 of the
 *   feature's half width from the curve;
 * - a cell's list: element texels, four per texel, -1 past the end.
 * Every element extends over the cells its width and profile reach, so that a cell never
 * needs its neighbours (s4.2). The work is linear in the number of elements and of the
 * cells they cover.
 *
 * Bad input is reported and left out, the rest drawn: paths with zero, negative or non
 * finite widths, zero-length segments, unknown profile or material indices (the default
 * profile, the actor's property), profiles of fewer than two points (replaced by the
 * default profile). A cell crossed by more than CellCapacity elements keeps the first of
 * them, with an error naming the grid resolution that avoids it. No paths at all give
 * an empty grid: the plain surface.
 */
#ifndef vtkPathFeatureTextureFilter_h
#define vtkPathFeatureTextureFilter_h

#include "vtkReliefFiltersModule.h" // For export macro
#include "vtkReliefWholeImagesAlgorithm.h"

#include <memory> // For Internal
#include <vector> // For ListCells

class vtkImageData;
class vtkPolyData;

class VTKRELIEFFILTERS_EXPORT vtkPathFeatureTextureFilter : public vtkReliefWholeImagesAlgorithm
{
public:
  static vtkPathFeatureTextureFilter* New();
  vtkTypeMacro(vtkPathFeatureTextureFilter, vtkReliefWholeImagesAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The most elements one cell lists: the shader's loop bound.
  static constexpr int CellCapacity = 32;
  /// The most points of a profile the shader reads; longer ones are thinned, with a warning.
  static constexpr int MaximumProfilePoints = 64;
  /// Texels per row of the data texture: 2^DataWidthBits, so that the shader finds a
  /// texel's row and column by shifting (an integer division is slow on CPU rasterizers).
  static constexpr int DataWidthBits = 10;
  static constexpr int DataWidth = 1 << DataWidthBits;
  /// The largest grid the filter makes on its own, per axis.
  static constexpr int MaximumAutomaticResolution = 512;
  /// Segments longer than this, in tiles, are split, so that a cell finds its copy of an
  /// element within half a tile.
  static constexpr double MaximumElementLength = 0.25;
  /// Consecutive elements of a path that turn by at most this are one feature to the
  /// antialiasing's region sampling (s5.7), which goes on straight through their joint
  /// where their outline strays less than an eighth of the pixel within its footprint: the
  /// pieces of a split segment (MaximumElementLength) and of a curve (a quadratic
  /// segment's, or a polyline's that follows one), not a corner.
  static constexpr double SmoothJointDegrees = 15.0;
  /// Consecutive elements that turn by at most this go on exactly: the shader ends each at
  /// the plane across the joint, not revolved about it (its neighbour's straight part goes
  /// on; where they turn more the planes would leave a sliver of the width times the turn).
  static constexpr double ExactJointRadians = 1e-6;

  ///@{
  /// The paths (port 0) and the profiles (port 1, optional).
  void SetPathsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetPathsData(vtkPolyData* paths);
  void SetProfilesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetProfilesData(vtkPolyData* profiles);
  ///@}

  ///@{
  /// The outputs: the grid (port 0) and the data (port 1).
  vtkImageData* GetGridOutput();
  vtkImageData* GetDataOutput();
  ///@}

  ///@{
  /**
   * Cells of the grid along u and v. (0, 0) (default): chosen so that a cell is about as
   * wide as the mean feature (the path-feature paper, s6 and Fig. 14), at most
   * MaximumAutomaticResolution a side. Negative values are taken as 0.
   */
  vtkSetVector2Macro(GridResolution, int);
  vtkGetVector2Macro(GridResolution, int);
  ///@}

  /// The grid resolution of the last update (GridResolution, or the one chosen).
  vtkGetVector2Macro(ResolutionUsed, int);

  ///@{
  /// The full width of paths without a "Width" array, in texture units. Default 0.02.
  vtkSetClampMacro(DefaultWidth, double, 1e-6, 1.0);
  vtkGetMacro(DefaultWidth, double);
  ///@}

  ///@{
  /**
   * Materials paths refer to by index ("Material"): diffuse colour (0 to 1), specular
   * intensity and specular power, as a vtkProperty has them. AddMaterial() returns the
   * new material's index.
   */
  int AddMaterial(double red, double green, double blue, double specular, double specularPower);
  void RemoveAllMaterials();
  int GetNumberOfMaterials();
  ///@}

  ///@{
  /// What the last update found: the depth of the base surface below the mesh, the
  /// deepest cut, the elements stored and the most listed in one cell.
  vtkGetMacro(BaseDepth, double);
  vtkGetMacro(MaximumDepth, double);
  vtkGetMacro(NumberOfElements, vtkIdType);
  vtkGetMacro(MaximumCellCount, int);
  ///@}

  /// Bytes of both textures as the last update made them.
  vtkIdType GetTextureBytes();

protected:
  vtkPathFeatureTextureFilter();
  ~vtkPathFeatureTextureFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

  int GridResolution[2] = { 0, 0 };
  int ResolutionUsed[2] = { 0, 0 };
  double DefaultWidth = 0.02;
  double BaseDepth = 0.0;
  double MaximumDepth = 0.0;
  vtkIdType NumberOfElements = 0;
  int MaximumCellCount = 0;

private:
  vtkPathFeatureTextureFilter(const vtkPathFeatureTextureFilter&) = delete;
  void operator=(const vtkPathFeatureTextureFilter&) = delete;

  /// Warns once per kind of bad input the paths held.
  void ReportPaths();
  /// BaseDepth and MaximumDepth of the paths read.
  void MeasureDepths();
  /// ResolutionUsed: GridResolution, or from the mean feature width.
  void ChooseResolution();
  /// Every cell's elements, in element order: cell c's are lists[offsets[c], offsets[c+1]).
  std::vector<int> ListCells(std::vector<int>& offsets);
  /// Each element's joins with its path's neighbours (the data texture's layout).
  std::vector<int> Joins() const;
  /// 0 (empty), 1 (one path, no end) or 2 (crossings and ends); notes self-crossings.
  int ClassifyCell(const int* begin, const int* end, int cell, std::vector<int>& selfCrossing);
  void WriteTextures(const std::vector<int>& offsets, const std::vector<int>& lists,
    vtkImageData* grid, vtkImageData* data);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

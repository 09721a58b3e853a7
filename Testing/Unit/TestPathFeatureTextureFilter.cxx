// vtkPathFeatureTextureFilter: the grid lists every element where its feature reaches and
// nowhere else, the data texture holds what the class description says, curves become
// pieces within tolerance, and each kind of bad input gives its message and sane output.
#include "ReliefEventRecorder.h"
#include "ReliefPathFixtures.h"

#include "vtkCommand.h"

#include <gtest/gtest.h>

#include <set>

namespace
{
using namespace ReliefPathFixtures;

struct FilterRun
{
  vtkNew<vtkPathFeatureTextureFilter> Filter;
  vtkNew<ReliefEventRecorder> Messages;
  ReliefCpuMirror::PathTextures Textures;

  FilterRun(vtkPolyData* paths, int resolution = 0, vtkPolyData* profiles = nullptr)
  {
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Messages);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Messages);
    this->Filter->SetPathsData(paths);
    if (profiles)
    {
      this->Filter->SetProfilesData(profiles);
    }
    this->Filter->SetGridResolution(resolution, resolution);
    this->Filter->Update();
    this->Textures = ReliefPathFixtures::Textures(this->Filter);
  }

  // the element texels cell (i, j) lists
  std::set<int> Listed(int i, int j) const
  {
    const glm::vec4 cell = this->Textures.Cell(glm::vec2(i, j));
    std::set<int> listed;
    for (int k = 0; k < static_cast<int>(cell.y); ++k)
    {
      listed.insert(
        static_cast<int>(this->Textures.Texel(static_cast<int>(cell.x) + k / 4)[k % 4]));
    }
    return listed;
  }
};

bool Reported(const FilterRun& run, unsigned long event, const char* text)
{
  return run.Messages->Count(event) > 0 && run.Messages->AnyMessageContains(text);
}
}

TEST(PathFeatureTextureFilter, ListsAnElementWhereverItsWidthReaches)
{
  Scene scene;
  scene.Paths.push_back({ { { 0.2, 0.5 }, { 0.4, 0.5 } }, 0.05 });
  FilterRun run(PathsData(scene.Paths));
  // a cell about as wide as the feature (s6): 1 / 0.05
  EXPECT_EQ(run.Filter->GetResolutionUsed()[0], 20);
  EXPECT_EQ(run.Filter->GetNumberOfElements(), 1);
  EXPECT_TRUE(run.Messages->Events.empty());
  const glm::vec4 header = run.Textures.Texel(0);
  EXPECT_EQ(header.x, 0.0f);          // nothing protrudes
  EXPECT_NEAR(header.y, 1.0f, 1e-6f); // the default groove's depth
  EXPECT_EQ(header.z, 20.0f);
  for (int j = 0; j < 20; ++j)
  {
    for (int i = 0; i < 20; ++i)
    {
      // within reach: the centre within half a width plus half a cell's diagonal
      const glm::dvec2 centre((i + 0.5) / 20, (j + 0.5) / 20);
      const glm::dvec2 nearest(glm::clamp(centre.x, 0.2, 0.4), 0.5);
      const bool reached = glm::length(centre - nearest) <= 0.025 + 0.5 * std::sqrt(2.0) / 20;
      EXPECT_EQ(run.Listed(i, j).size(), reached ? 1u : 0u) << i << " " << j;
      const glm::vec4 cell = run.Textures.Cell(glm::vec2(i, j));
      // kind 2 where an end's cap reaches the cell, 1 elsewhere along the path
      const double reach = 0.025 + 0.5 * std::sqrt(2.0) / 20;
      const bool nearEnd = glm::length(centre - glm::dvec2(0.2, 0.5)) <= reach ||
        glm::length(centre - glm::dvec2(0.4, 0.5)) <= reach;
      EXPECT_EQ(cell.w, reached ? (nearEnd ? 2.0f : 1.0f) : 0.0f) << "kind of " << i << " " << j;
    }
  }
}

TEST(PathFeatureTextureFilter, DataTexelsHoldPathsProfilesAndMaterials)
{
  Scene scene;
  scene.Profiles = { { { -1, 0 }, { 0, -0.5 }, { 1, 0 } } };
  PathSpec path{ { { 0.1, 0.1 }, { 0.9, 0.1 } }, 0.1, 0, 3 };
  path.ScaleEnd = 0.5;
  scene.Paths.push_back(path);
  vtkSmartPointer<vtkPolyData> paths = PathsData(scene.Paths, { 0 });
  vtkNew<vtkPathFeatureTextureFilter> filter;
  EXPECT_EQ(filter->AddMaterial(0.8, 0.2, 0.1, 0.5, 20.0), 0);
  filter->SetPathsData(paths);
  filter->SetProfilesData(ProfilesData(scene.Profiles));
  filter->Update();
  const ReliefCpuMirror::PathTextures textures = Textures(filter);
  // protrusion: the base 0.5 below the polygons
  EXPECT_NEAR(filter->GetBaseDepth(), 0.5, 1e-7);
  EXPECT_NEAR(filter->GetMaximumDepth(), 0.5, 1e-7);
  // the profile at texel 1: 3 points, reaching 1 across, 0.5 up
  EXPECT_EQ(textures.Texel(1), glm::vec4(3, 1, -0.5f, 0));
  // the material at 4 (after the profile's header and two texels of points)
  EXPECT_EQ(textures.Texel(4), glm::vec4(0.8f, 0.2f, 0.1f, 0.5f));
  EXPECT_EQ(textures.Texel(5).x, 20.0f);
  // the path at 6: half width, profile, material, priority; scales and length
  EXPECT_EQ(textures.Texel(6), glm::vec4(0.05f, 1, 4, 3));
  EXPECT_NEAR(textures.Texel(7).y, 0.5f, 1e-7f);
  EXPECT_NEAR(textures.Texel(7).z, 0.8f, 1e-6f);
  EXPECT_EQ(textures.Texel(7).w, 0.0f); // the profile is centred
  // 0.8 long: four elements of at most a quarter tile, end to end
  EXPECT_EQ(filter->GetNumberOfElements(), 4);
  for (int e = 0; e < 4; ++e)
  {
    const glm::vec4 ends = textures.Texel(8 + 2 * e);
    EXPECT_NEAR(ends.x, 0.1f + 0.2f * e, 1e-6f);
    EXPECT_NEAR(ends.z, 0.1f + 0.2f * (e + 1), 1e-6f);
    EXPECT_EQ(textures.Texel(9 + 2 * e).x, 6.0f);
    EXPECT_NEAR(textures.Texel(9 + 2 * e).y, 0.2f * e, 1e-6f);
    // joined straight, and exactly, to the previous piece (1 + 4) and to the next (2 + 8),
    // not at the path's ends
    EXPECT_EQ(textures.Texel(9 + 2 * e).w, (e > 0 ? 5.0f : 0.0f) + (e < 3 ? 10.0f : 0.0f));
  }
  EXPECT_GT(filter->GetTextureBytes(), 0);
}

TEST(PathFeatureTextureFilter, CurvesBecomePiecesWithinTolerance)
{
  // a quadratic through its control point (0.5, 0.9) from (0.1, 0.5) to (0.9, 0.5)
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.1, 0.5, 0);
  points->InsertNextPoint(0.5, 0.9, 0);
  points->InsertNextPoint(0.9, 0.5, 0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[3] = { 0, 1, 2 };
  lines->InsertNextCell(3, ids);
  vtkNew<vtkIntArray> control;
  control->SetName("ControlPoint");
  control->InsertNextValue(0);
  control->InsertNextValue(1);
  control->InsertNextValue(0);
  vtkNew<vtkPolyData> paths;
  paths->SetPoints(points);
  paths->SetLines(lines);
  paths->GetPointData()->AddArray(control);
  FilterRun run(paths);
  const vtkIdType elements = run.Filter->GetNumberOfElements();
  ASSERT_GT(elements, 4);
  const double halfWidth = 0.01; // the default width's half
  const int first = 1 + 6;       // after the header, the default profile (1 + 5) and the path (2)
  for (vtkIdType e = 0; e < elements; ++e)
  {
    const glm::vec4 ends = run.Textures.Texel(first + 2 + 2 * static_cast<int>(e));
    // each chord's middle within 1/50 of the half width of the curve: the curve is
    // v = 0.5 + 0.4 (1 - ((u - 0.5) / 0.4)^2) / 2 ... sampled by distance
    const glm::dvec2 middle(0.5 * (ends.x + ends.z), 0.5 * (ends.y + ends.w));
    double nearest = 1e9;
    for (int k = 0; k <= 20000; ++k)
    {
      const double s = k / 20000.0;
      const glm::dvec2 curve = (1 - s) * (1 - s) * glm::dvec2(0.1, 0.5) +
        2 * s * (1 - s) * glm::dvec2(0.5, 0.9) + s * s * glm::dvec2(0.9, 0.5);
      nearest = std::min(nearest, glm::length(curve - middle));
    }
    EXPECT_LE(nearest, 0.02 * halfWidth + 1e-6) << "element " << e;
    // the pieces go on smoothly, not exactly (region sampling goes on through them): 1 to
    // the previous, 2 to the next; the shader revolves each end where the path turns, and
    // the default groove is centred, so a piece's start is not (+ 4): the previous one's
    // revolved end holds all of it
    const float joins = run.Textures.Texel(first + 3 + 2 * static_cast<int>(e)).w;
    EXPECT_EQ(joins, (e > 0 ? 1.0f + 4.0f : 0.0f) + (e + 1 < elements ? 2.0f : 0.0f)) << e;
  }
}

// A corner that turns by more than SmoothJointDegrees joins nothing: region sampling
// stops at it; by less, the two segments go on (not exactly). Either way the second
// segment's start is not revolved (+ 4, RevolvedOnceAtJoints).
TEST(PathFeatureTextureFilter, CornersJoinNothing)
{
  for (const double degrees : { 20.0, 10.0 })
  {
    const double turn = degrees * M_PI / 180.0;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0.1, 0.5, 0);
    points->InsertNextPoint(0.3, 0.5, 0);
    points->InsertNextPoint(0.3 + 0.2 * std::cos(turn), 0.5 + 0.2 * std::sin(turn), 0);
    vtkNew<vtkCellArray> lines;
    const vtkIdType ids[3] = { 0, 1, 2 };
    lines->InsertNextCell(3, ids);
    vtkNew<vtkPolyData> paths;
    paths->SetPoints(points);
    paths->SetLines(lines);
    FilterRun run(paths);
    ASSERT_EQ(run.Filter->GetNumberOfElements(), 2);
    const int first = 1 + 6; // after the header, the default profile and the path
    const bool smooth = degrees <= vtkPathFeatureTextureFilter::SmoothJointDegrees;
    EXPECT_EQ(run.Textures.Texel(first + 3).w, smooth ? 2.0f : 0.0f) << degrees;
    EXPECT_EQ(run.Textures.Texel(first + 5).w, smooth ? 1.0f + 4.0f : 4.0f) << degrees;
  }
}

// Where a path turns, the shader revolves the profile beyond the first element's end and
// before the second's start; where the profile is centred (at every depth one interval
// about x = 0), adds or cuts but not both, and keeps one scale, the first's revolved end
// holds all the second's does (its straight part holds the rest), so the second's start
// is not revolved (+ 4 in its joins); the first's end instead (+ 8) where the first is
// shorter than the profile's reach; both elsewhere (ReliefPathSearch.CornersRevolveOnce
// checks the surfaces against the marched reference). A path whose profile is not centred
// is flagged: beyond its revolved ends the shader meets the plane where their halves meet.
TEST(PathFeatureTextureFilter, RevolvedOnceAtJoints)
{
  const std::vector<dvec2> vee = { { -1.0, 0.0 }, { 0.0, 1.0 }, { 1.0, 0.0 } };
  const std::vector<dvec2> ridge = { { -1.0, 0.0 }, { 0.0, -0.5 }, { 1.0, 0.0 } };
  const std::vector<dvec2> dovetail = { { -0.5, 0.0 }, { -1.0, 0.6 }, { 1.0, 0.6 }, { 0.5, 0.0 } };
  const std::vector<dvec2> diamond = { { -1.0, 0.0 }, { 0.0, -0.5 }, { 1.0, 0.0 }, { 0.0, 0.5 } };
  const std::vector<dvec2> notches = { { -1.0, 0.0 }, { -0.6, 0.5 }, { -0.2, 0.0 }, { 0.2, 0.0 },
    { 0.6, 0.5 }, { 1.0, 0.0 } };
  const std::vector<dvec2> slanted = { { -1.0, 0.0 }, { 0.5, 1.0 }, { 1.0, 0.0 } };
  const std::vector<dvec2> rimmed = { { -1.0, 0.0 }, { -0.7, -0.2 }, { -0.4, 0.0 }, { 0.0, 0.8 },
    { 0.4, 0.0 }, { 0.7, -0.2 }, { 1.0, 0.0 } };
  struct Case
  {
    std::vector<dvec2> Profile;
    dvec2 First; // the first segment's start (the corner is at (0.3, 0.5))
    double ScaleEnd;
    float Start; // the second element's start bit, and the first's end bit
    float End;
    float OffCentre; // the path's flag (its second texel's fourth value)
    const char* What;
  };
  const std::vector<Case> cases = { { vee, { 0.1, 0.5 }, 1.0, 4.0f, 0.0f, 0.0f, "a vee" },
    { ridge, { 0.1, 0.5 }, 1.0, 4.0f, 0.0f, 0.0f, "a ridge" },
    { vee, { 0.299, 0.5 }, 1.0, 0.0f, 8.0f, 0.0f, "a vee after a short element" },
    { dovetail, { 0.1, 0.5 }, 1.0, 4.0f, 0.0f, 0.0f, "a dovetail (wider below, centred)" },
    { notches, { 0.1, 0.5 }, 1.0, 0.0f, 0.0f, 1.0f, "two notches (two intervals)" },
    { slanted, { 0.1, 0.5 }, 1.0, 0.0f, 0.0f, 1.0f, "an off-centre vee" },
    { rimmed, { 0.1, 0.5 }, 1.0, 0.0f, 0.0f, 1.0f, "a cut with rims (two intervals above)" },
    { diamond, { 0.1, 0.5 }, 1.0, 0.0f, 0.0f, 0.0f, "a diamond (centred, cuts and adds)" },
    { vee, { 0.1, 0.5 }, 0.5, 0.0f, 0.0f, 0.0f, "a narrowing vee" } };
  for (const Case& c : cases)
  {
    Scene scene;
    scene.Profiles = { c.Profile };
    PathSpec path{ { c.First, { 0.3, 0.5 }, { 0.3, 0.7 } }, 0.02, 0 };
    path.ScaleEnd = c.ScaleEnd;
    scene.Paths.push_back(path);
    FilterRun run(PathsData(scene.Paths), 0, ProfilesData(scene.Profiles));
    ASSERT_EQ(run.Filter->GetNumberOfElements(), 2) << c.What;
    // after the header, the profile (1 + its pairs of points) and the path (2)
    const int first = 1 + 1 + static_cast<int>(c.Profile.size() + 1) / 2 + 2;
    EXPECT_EQ(run.Textures.Texel(first - 1).w, c.OffCentre) << c.What;
    EXPECT_EQ(run.Textures.Texel(first + 1).w, c.End) << c.What;
    EXPECT_EQ(run.Textures.Texel(first + 3).w, c.Start) << c.What;
  }
}

TEST(PathFeatureTextureFilter, TilesPathsBeyondTheUnitSquare)
{
  Scene scene;
  scene.Paths.push_back({ { { 2.9, -0.5 }, { 3.1, -0.5 } }, 0.1 });
  FilterRun run(PathsData(scene.Paths), 10);
  // moved into the first tile, listed on both sides of its edge
  EXPECT_EQ(run.Listed(9, 5).size(), 1u);
  EXPECT_EQ(run.Listed(0, 5).size(), 1u);
  EXPECT_EQ(run.Listed(4, 5).size(), 0u);
  const glm::vec4 ends = run.Textures.Texel(1 + 6 + 2);
  EXPECT_NEAR(ends.x, 0.9f, 1e-6f);
  EXPECT_NEAR(ends.y, 0.5f, 1e-6f);
}

TEST(PathFeatureTextureFilter, BadInputIsReportedAndLeftOut)
{
  Scene scene;
  scene.Paths.push_back({ { { 0.1, 0.1 }, { 0.5, 0.1 } }, 0.0 });     // zero width
  scene.Paths.push_back({ { { 0.1, 0.2 }, { 0.5, 0.2 } }, -1.0 });    // negative
  scene.Paths.push_back({ { { 0.1, 0.3 }, { 0.1, 0.3 } }, 0.05 });    // no length
  scene.Paths.push_back({ { { 0.1, 0.4 }, { 0.5, 0.4 } }, 0.05, 7 }); // unknown profile
  scene.Paths.push_back({ { { 0.1, 0.6 }, { 0.5, 0.6 }, { 0.5, 0.6 }, { 0.9, 0.6 } }, 0.05 });
  scene.Paths.push_back({ { { 0.1, 0.7 }, { 0.9, 0.9 }, { 0.9, 0.7 }, { 0.2, 0.9 } }, 0.05 });
  vtkSmartPointer<vtkPolyData> paths = PathsData(scene.Paths);
  vtkNew<vtkIntArray> materials;
  materials->SetName("Material");
  for (int k = 0; k < 6; ++k)
  {
    materials->InsertNextValue(k == 4 ? 2 : -1); // no material was added
  }
  paths->GetCellData()->AddArray(materials);
  FilterRun run(paths, 16);
  EXPECT_TRUE(Reported(run, vtkCommand::WarningEvent, "zero, negative or non-finite \"Width\""));
  EXPECT_TRUE(Reported(run, vtkCommand::WarningEvent, "zero-length segment"));
  EXPECT_TRUE(Reported(run, vtkCommand::WarningEvent, "name a profile out of the 1"));
  EXPECT_TRUE(Reported(run, vtkCommand::WarningEvent, "actor's property"));
  EXPECT_TRUE(Reported(run, vtkCommand::WarningEvent, "cross themselves"));
  // drawn, in pieces of at most a quarter tile: the unknown profile's path (0.4 long),
  // the repeated point's (0.4 twice) and the crossing one's (0.82, 0.2, 0.73)
  EXPECT_EQ(run.Filter->GetNumberOfElements(), 2 + (2 + 2) + (4 + 1 + 3));
}

TEST(PathFeatureTextureFilter, ProfilesOfFewerThanTwoPointsAreReplaced)
{
  Scene scene;
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1 });
  FilterRun run(PathsData(scene.Paths), 0, ProfilesData({ { { 0.0, 1.0 } } }));
  EXPECT_TRUE(Reported(run, vtkCommand::ErrorEvent, "fewer than two points"));
  EXPECT_EQ(run.Textures.Texel(1).x, 9.0f); // the default groove's points
}

TEST(PathFeatureTextureFilter, OverfullCellsNameTheResolutionThatAvoidsThem)
{
  Scene scene;
  for (int k = 0; k < 40; ++k)
  {
    const double v = 0.3 + 0.4 * k / 40.0;
    scene.Paths.push_back({ { { 0.1, v }, { 0.9, v } }, 0.01 });
  }
  FilterRun run(PathsData(scene.Paths), 2);
  EXPECT_TRUE(Reported(run, vtkCommand::ErrorEvent, "Set GridResolution to"));
  EXPECT_GT(run.Filter->GetMaximumCellCount(), vtkPathFeatureTextureFilter::CellCapacity);
  EXPECT_EQ(run.Textures.Cell(glm::vec2(0, 0)).y, vtkPathFeatureTextureFilter::CellCapacity);
  // at the automatic resolution the same paths fit
  FilterRun automatic(PathsData(scene.Paths));
  EXPECT_TRUE(automatic.Messages->Events.empty());
  EXPECT_LE(automatic.Filter->GetMaximumCellCount(), vtkPathFeatureTextureFilter::CellCapacity);
}

TEST(PathFeatureTextureFilter, NoPathsMakeThePlainSurface)
{
  vtkNew<vtkPolyData> empty;
  FilterRun run(empty);
  EXPECT_TRUE(run.Messages->Events.empty());
  EXPECT_EQ(run.Filter->GetResolutionUsed()[0], 1);
  EXPECT_EQ(run.Textures.Cell(glm::vec2(0, 0)).y, 0.0f);
  EXPECT_EQ(run.Textures.Texel(0), glm::vec4(0, 0, 1, 1));
}

#include "vtkOpenGLReliefImpostorMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefArrayTexture.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefImpostorFilter.h"
#include "vtkReliefSearchMethod.h"
#include "vtkReliefShaderRewrites.h"
#include "vtkScalarsToColors.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include "vtkReliefCommon.h"
#include "vtkReliefGridSearch.h"
#include "vtkReliefImpostorFragmentDec.h"
#include "vtkReliefImpostorFragmentImpl.h"
#include "vtkReliefImpostorFrame.h"
#include "vtkReliefSearch.h"

#include <algorithm>
#include <sstream>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkOpenGLReliefImpostorMapper);

namespace
{
// View `view`'s frame for normals, a rotation, as a row-major 4x4 matrix from the frame to
// model axes: x along the next axis after the view's, z out of its face (toward what it
// sees).
void NormalFrame(int view, int views, double frame[16])
{
  const int axis = views == 1 ? 2 : view / 2;
  const double sign = views == 1 || view % 2 == 0 ? 1.0 : -1.0;
  std::fill(frame, frame + 16, 0.0);
  frame[4 * ((axis + 1) % 3)] = 1.0;
  frame[4 * ((axis + 2) % 3) + 1] = sign;
  frame[4 * axis + 2] = sign;
  frame[15] = 1.0;
}

// A unit vector's octahedral coordinates in [-1, 1]^2 (Cigolle et al. 2014, "A survey of
// efficient representations for independent unit vectors", s3.3): the vector over its
// 1-norm, the lower half folded out over the diagonals; vtkReliefImpostorFragmentDec.glsl
// unfolds it. Filtered bilinearly and across mipmaps as two channels, it stays close to
// the mean of the normals except across the fold, which each view's frame (NormalFrame)
// keeps behind what the view sees: seen from below, in model axes, every normal a view
// holds would lie on the fold.
void EncodeOctahedral(const double normal[3], double encoded[2])
{
  const double norm = std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]);
  if (!(norm > 0.0) || !std::isfinite(norm))
  {
    encoded[0] = encoded[1] = 0.0; // no normal: +z
    return;
  }
  const double x = normal[0] / norm;
  const double y = normal[1] / norm;
  if (normal[2] >= 0.0)
  {
    encoded[0] = x;
    encoded[1] = y;
    return;
  }
  encoded[0] = (1.0 - std::abs(y)) * (x >= 0.0 ? 1.0 : -1.0);
  encoded[1] = (1.0 - std::abs(x)) * (y >= 0.0 ? 1.0 : -1.0);
}

// Fills the texels of a size x size layer of `channels` values that nothing covered
// (coverage 0) from the covered texels around them, the nearest weighing most: push-pull
// (Gortler et al. 1996, "The Lumigraph", s3.5.2), coverage-weighted means pulled up a
// pyramid, then pushed down into the empty texels. A layer that saw nothing is kept.
void FillEmptyTexels(float* values, int channels, const float* coverage, int size)
{
  struct Level
  {
    int Size;
    std::vector<float> Sums; // coverage-weighted
    std::vector<float> Weights;
  };
  std::vector<Level> levels(1);
  levels[0].Size = size;
  const size_t texels = static_cast<size_t>(size) * size;
  levels[0].Weights.assign(coverage, coverage + texels);
  levels[0].Sums.resize(texels * channels);
  for (size_t k = 0; k < texels * channels; ++k)
  {
    levels[0].Sums[k] = values[k] * coverage[k / channels];
  }
  while (levels.back().Size > 1)
  {
    const Level& fine = levels.back();
    Level coarse;
    coarse.Size = (fine.Size + 1) / 2;
    coarse.Weights.assign(static_cast<size_t>(coarse.Size) * coarse.Size, 0.0f);
    coarse.Sums.assign(coarse.Weights.size() * channels, 0.0f);
    for (int j = 0; j < fine.Size; ++j)
    {
      for (int i = 0; i < fine.Size; ++i)
      {
        const size_t from = static_cast<size_t>(j) * fine.Size + i;
        const size_t to = static_cast<size_t>(j / 2) * coarse.Size + i / 2;
        coarse.Weights[to] += fine.Weights[from];
        for (int c = 0; c < channels; ++c)
        {
          coarse.Sums[to * channels + c] += fine.Sums[from * channels + c];
        }
      }
    }
    levels.push_back(std::move(coarse));
  }
  if (!(levels.back().Weights[0] > 0.0f))
  {
    return;
  }
  for (size_t level = levels.size() - 1; level-- > 0;)
  {
    Level& fine = levels[level];
    const Level& coarse = levels[level + 1];
    for (int j = 0; j < fine.Size; ++j)
    {
      for (int i = 0; i < fine.Size; ++i)
      {
        const size_t at = static_cast<size_t>(j) * fine.Size + i;
        const size_t parent = static_cast<size_t>(j / 2) * coarse.Size + i / 2;
        if (fine.Weights[at] > 0.0f)
        {
          continue;
        }
        fine.Weights[at] = 1.0f;
        for (int c = 0; c < channels; ++c)
        {
          fine.Sums[at * channels + c] =
            coarse.Sums[parent * channels + c] / coarse.Weights[parent];
        }
      }
    }
  }
  for (size_t k = 0; k < texels; ++k)
  {
    for (int c = 0; c < channels; ++c)
    {
      values[k * channels + c] = levels[0].Sums[k * channels + c] / levels[0].Weights[k];
    }
  }
}

using Mapper = vtkOpenGLReliefMapper;

// A key matrix of VTK's (stored transposed) as the matrix it stands for.
void FromKeyMatrix(vtkMatrix4x4* key, vtkMatrix4x4* matrix)
{
  vtkMatrix4x4::Transpose(key, matrix);
}

// `matrix` as the GLSL mat4 uniform `name`: vtkShaderProgram uploads a vtkMatrix4x4's
// rows as the columns of the GLSL matrix.
void SetMatrixUniform(vtkShaderProgram* program, const char* name, vtkMatrix4x4* matrix)
{
  vtkNew<vtkMatrix4x4> transposed;
  vtkMatrix4x4::Transpose(matrix, transposed);
  program->SetUniformMatrix(name, transposed);
}

// `count` row-major 4x4 matrices as the GLSL mat4 array uniform `name`, column-major.
void SetMatrixArrayUniform(
  vtkShaderProgram* program, const char* name, const double (*matrices)[16], int count)
{
  std::vector<float> columns(16 * static_cast<size_t>(count));
  for (int k = 0; k < count; ++k)
  {
    for (int row = 0; row < 4; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        columns[16 * k + 4 * column + row] = static_cast<float>(matrices[k][4 * row + column]);
      }
    }
  }
  program->SetUniformMatrix4x4v(name, count, columns.data());
}

// One layer of `image` (a slice of the capture), as it is laid out in memory.
vtkIdType LayerTexels(vtkImageData* image)
{
  return static_cast<vtkIdType>(image->GetDimensions()[0]) * image->GetDimensions()[1];
}
}

vtkOpenGLReliefImpostorMapper::vtkOpenGLReliefImpostorMapper()
{
  vtkReliefForwardMessages(this->ImpostorFilter, this);
  this->SetAutomaticResolution(true);
}

void vtkOpenGLReliefImpostorMapper::SetAutomaticResolution(bool automatic)
{
  if (automatic == this->AutomaticResolution && this->AppliedDepthResolution != 0)
  {
    return;
  }
  this->AutomaticResolution = automatic;
  this->Modified();
  if (automatic)
  {
    // from the least, raised by the next renders as they need
    this->ApplyResolution(MinimumAutomaticResolution);
  }
}

void vtkOpenGLReliefImpostorMapper::SetCompressColours(bool compress)
{
  if (compress != this->CompressColours)
  {
    this->CompressColours = compress;
    this->UploadedCaptureTime = 0; // uploaded again, in the other format
    this->FailedCaptureTime = 0;   // which may succeed where this one failed
    this->Modified();
  }
}

double vtkOpenGLReliefImpostorMapper::ScreenSpan(
  const double bounds[6], vtkRenderer* ren, vtkActor* actor)
{
  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  vtkMatrix4x4* worldToClip =
    ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
      ren->GetTiledAspectRatio(), -1.0, 1.0);
  vtkNew<vtkMatrix4x4> modelToClip;
  vtkMatrix4x4::Multiply4x4(worldToClip, actor->GetMatrix(), modelToClip);
  double low[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double high[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double model[4] = { bounds[corner & 1], bounds[2 + (corner >> 1 & 1)],
      bounds[4 + (corner >> 2)], 1.0 };
    double clip[4];
    modelToClip->MultiplyPoint(model, clip);
    if (clip[3] <= 0.0)
    {
      return std::max(width, height); // the box reaches behind the eye: the whole viewport
    }
    for (int axis = 0; axis < 2; ++axis)
    {
      low[axis] = std::min(low[axis], clip[axis] / clip[3]);
      high[axis] = std::max(high[axis], clip[axis] / clip[3]);
    }
  }
  // clipped to the viewport: what lies outside it needs no texels
  const double across = 0.5 * width * (std::min(high[0], 1.0) - std::max(low[0], -1.0));
  const double down = 0.5 * height * (std::min(high[1], 1.0) - std::max(low[1], -1.0));
  return std::max({ across, down, 0.0 });
}

bool vtkOpenGLReliefImpostorMapper::BakingShadows(vtkActor* actor)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  vtkInformationObjectBaseVectorKey* passes = vtkOpenGLRenderPass::RenderPasses();
  for (int k = 0; keys && keys->Has(passes) && k < keys->Length(passes); ++k)
  {
    if (vtkShadowMapBakerPass::SafeDownCast(keys->Get(passes, k)))
    {
      return true;
    }
  }
  return false;
}

void vtkOpenGLReliefImpostorMapper::FollowScreenSize(vtkRenderer* ren, vtkActor* actor)
{
  vtkReliefImpostorFilter* filter = this->ImpostorFilter;
  if (filter->GetDepthResolution() != this->AppliedDepthResolution ||
    filter->GetColourResolution() != 2 * this->AppliedDepthResolution)
  {
    this->AutomaticResolution = false; // the user's own resolutions
  }
  // the shadow baker draws through the light's camera, which says nothing of the view's
  if (!this->AutomaticResolution || BakingShadows(actor))
  {
    return;
  }
  const double span = ScreenSpan(this->GetBounds(), ren, actor);
  int wanted = MinimumAutomaticResolution;
  while (wanted < span && wanted < MaximumAutomaticResolution)
  {
    wanted *= 2;
  }
  if (wanted > this->AppliedDepthResolution)
  {
    this->ApplyResolution(wanted);
  }
}

void vtkOpenGLReliefImpostorMapper::ApplyResolution(int depthResolution)
{
  this->AppliedDepthResolution = depthResolution;
  this->ImpostorFilter->SetDepthResolution(depthResolution);
  this->ImpostorFilter->SetColourResolution(2 * depthResolution);
}

vtkOpenGLReliefImpostorMapper::~vtkOpenGLReliefImpostorMapper() = default;

vtkReliefImpostorFilter* vtkOpenGLReliefImpostorMapper::GetImpostorFilter()
{
  return this->ImpostorFilter;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefImpostorMapper::SetSearchMethod(int method)
{
  if (!vtkReliefSearchMethod::Get(method))
  {
    vtkWarningMacro("Unknown search method " << method << ": use one of "
                    "vtkOpenGLReliefMapper::SearchMethods. The method is left as it was.");
    return;
  }
  if (method != this->SearchMethod)
  {
    this->SearchMethod = method;
    this->WarnedSearchMethod = false;
    this->Modified();
  }
}

int vtkOpenGLReliefImpostorMapper::ImpostorSearchMethod(int method)
{
  switch (method)
  {
    case Mapper::LINEAR:
    case Mapper::LINEAR_BINARY:
    case Mapper::SECANT:
    case Mapper::EXACT_DDA:
      return method;
    default:
      return Mapper::MAXIMUM_MIPMAP;
  }
}

const vtkReliefSearchMethod& vtkOpenGLReliefImpostorMapper::GetActiveSearch()
{
  return *vtkReliefSearchMethod::Get(this->ActiveSearchMethod);
}

void vtkOpenGLReliefImpostorMapper::SetLinearSteps(int steps)
{
  const int clamped = std::min(std::max(steps, 1), 4096);
  if (clamped != steps)
  {
    vtkWarningMacro("LinearSteps " << steps << " is out of [1, 4096]: " << clamped << " is used.");
  }
  if (clamped != this->LinearSteps)
  {
    this->LinearSteps = clamped;
    this->Modified();
  }
}

void vtkOpenGLReliefImpostorMapper::SetBinarySteps(int steps)
{
  const int clamped = std::min(std::max(steps, 0), 32);
  if (clamped != steps)
  {
    vtkWarningMacro("BinarySteps " << steps << " is out of [0, 32]: " << clamped << " is used.");
  }
  if (clamped != this->BinarySteps)
  {
    this->BinarySteps = clamped;
    this->Modified();
  }
}

void vtkOpenGLReliefImpostorMapper::SetConservativeDepth(bool conservative)
{
  if (conservative != this->ConservativeDepth)
  {
    this->ConservativeDepth = conservative;
    this->WarnedCameraInside = false; // said once a setting: actors sharing the mapper
    this->Modified();                 // may see the camera inside some boxes, not others
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefImpostorMapper::ComputeBounds()
{
  vtkPolyData* mesh = this->GetInput();
  double bounds[6];
  if (!mesh || mesh->GetNumberOfCells() == 0)
  {
    // asked before any render: an empty actor is culled before it draws
    this->WarnEmptyMesh();
    vtkMath::UninitializeBounds(this->Bounds);
    return;
  }
  this->WarnedEmptyMesh = false;
  mesh->GetBounds(bounds);
  vtkReliefImpostorFilter::PadBounds(bounds, this->ImpostorFilter->GetPadding(), this->Bounds);
}

void vtkOpenGLReliefImpostorMapper::RenderPiece(vtkRenderer* ren, vtkActor* actor)
{
  vtkPolyData* mesh = this->GetInput();
  if (mesh && !this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  if (mesh && mesh->GetNumberOfCells() == 0)
  {
    this->WarnEmptyMesh();
    this->DrawingImpostor = false;
    return;
  }
  this->WarnedEmptyMesh = false;
  this->Superclass::RenderPiece(ren, actor);
}

void vtkOpenGLReliefImpostorMapper::WarnEmptyMesh()
{
  if (!this->WarnedEmptyMesh)
  {
    this->WarnedEmptyMesh = true;
    vtkWarningMacro("The impostor's mesh is empty: nothing is drawn. Connect a surface mesh "
                    "with polygons to port 0.");
  }
}

vtkPolyData* vtkOpenGLReliefImpostorMapper::ColouredMesh(vtkPolyData* mesh)
{
  // VTK's mapper colours a mesh's points through this mapper's lookup table, range and
  // array selection: the capture takes those very colours (RGBA, used as they are)
  int cellFlag = 0;
  vtkAbstractArray* scalars = vtkAbstractMapper::GetAbstractScalars(mesh, this->ScalarMode,
    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  const bool mapped = this->ScalarVisibility && scalars && cellFlag == 0;
  // without colours of its own, white (the actor's colour multiplies it), unless the
  // capture reads a colour texture
  const bool textured = this->ImpostorFilter->GetNumberOfInputConnections(1) > 0;
  // the table as vtkMapper::MapScalars picks it: the array's own, else this mapper's, built
  vtkDataArray* values = vtkDataArray::SafeDownCast(scalars);
  vtkScalarsToColors* table = nullptr;
  if (mapped)
  {
    table = this->GetLookupTable();
    if (values && values->GetLookupTable())
    {
      table = values->GetLookupTable();
    }
    table->Build();
    if (!this->UseLookupTableScalarRange)
    {
      table->SetRange(this->ScalarRange); // an unchanged range changes nothing
    }
  }
  this->ScalarColours = mapped;
  std::ostringstream key;
  key << mesh << ' ' << mesh->GetMTime() << ' ' << scalars << ' ' << mapped << ' ' << textured
      << ' ' << (table ? table->GetMTime() : 0) << ' ' << this->ColorMode << ' '
      << this->ArrayComponent;
  if (key.str() == this->ColouredKey)
  {
    return this->Coloured;
  }
  this->ColouredKey = key.str();
  this->Coloured->ShallowCopy(mesh);
  vtkSmartPointer<vtkUnsignedCharArray> colours;
  if (mapped)
  {
    colours.TakeReference(table->MapScalars(scalars, this->ColorMode, this->ArrayComponent));
  }
  else if (!textured)
  {
    colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(4);
    colours->SetNumberOfTuples(mesh->GetNumberOfPoints());
    colours->Fill(255);
  }
  // the copy's point data is its own: the mesh keeps its active scalars
  if (colours)
  {
    colours->SetName("ImpostorColours");
  }
  this->Coloured->GetPointData()->SetScalars(colours);
  return this->Coloured;
}

bool vtkOpenGLReliefImpostorMapper::UpdateImpostor(vtkRenderer* ren, vtkActor* actor)
{
  this->FollowScreenSize(ren, actor);
  this->ImpostorFilter->SetInputData(this->ColouredMesh(this->CurrentInput));
  this->ImpostorFilter->Update();
  vtkImageData* depths = this->ImpostorFilter->GetDepthOutput();
  const bool captured = depths->GetNumberOfPoints() > 0;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  const int active = ImpostorSearchMethod(this->SearchMethod);
  if (active != this->SearchMethod && this->SearchMethod != Mapper::AUTOMATIC &&
    !this->WarnedSearchMethod)
  {
    this->WarnedSearchMethod = true;
    vtkWarningMacro(<< Mapper::GetSearchMethodAsString(this->SearchMethod)
                    << " cannot search an impostor: it steps only along rays that descend "
                       "into a field, and the views behind the object are searched along "
                       "rays that rise. MaximumMipmap, exact, searches instead.");
  }
  if (active != this->ActiveSearchMethod)
  {
    this->ActiveSearchMethod = active;
    this->ShaderOptionsTime.Modified();
  }
  const bool pyramid = this->GetActiveSearch().NeedsAcceleration();
  const bool failedBefore = this->FailedCaptureTime == depths->GetMTime() &&
    this->FailedWindow == window && this->FailedPyramid == pyramid;
  if (captured && failedBefore)
  {
    return false; // said when it failed
  }
  if (captured &&
    (this->UploadedCaptureTime < depths->GetMTime() || this->UploadedWindow != window ||
      this->UploadedPyramid != pyramid))
  {
    const int views = this->Views;
    this->UploadedCaptureTime = 0;
    if (!this->UploadTextures(window))
    {
      this->ReleaseTextures(window);
      this->FailedCaptureTime = depths->GetMTime();
      this->FailedWindow = window;
      this->FailedPyramid = pyramid;
      return this->WarnFallback(
        "its textures could not be made on this OpenGL (see the message above)");
    }
    this->UploadedCaptureTime = depths->GetMTime();
    this->UploadedWindow = window;
    this->UploadedPyramid = pyramid;
    if (views != this->Views)
    {
      this->ShaderOptionsTime.Modified();
    }
    this->MakeBox();
  }
  if (!captured)
  {
    return this->WarnFallback("the capture failed (see vtkReliefImpostorFilter's error)");
  }
  this->WarnedFallback = false;
  return true;
}

bool vtkOpenGLReliefImpostorMapper::WarnFallback(const char* why)
{
  if (!this->WarnedFallback)
  {
    this->WarnedFallback = true;
    vtkWarningMacro("The impostor cannot be drawn: " << why << ". The mesh itself is drawn "
                                                         "instead.");
  }
  return false;
}

bool vtkOpenGLReliefImpostorMapper::UploadTextures(vtkOpenGLRenderWindow* window)
{
  vtkImageData* depths = this->ImpostorFilter->GetDepthOutput();
  vtkImageData* colours = this->ImpostorFilter->GetColourOutput();
  const int depthSize = depths->GetDimensions()[0];
  const int colourSize = colours->GetDimensions()[0];
  const int views = depths->GetDimensions()[2];
  const bool pyramid = this->GetActiveSearch().NeedsAcceleration();
  const int widest = std::max(colourSize, depthSize);
  const int limit = vtkTextureObject::GetMaximumTextureSize(window);
  if (widest > limit)
  {
    vtkErrorMacro("The capture's textures (" << widest << " texels wide) exceed this OpenGL's "
                                                "largest, "
                                             << limit
                                             << ": lower the impostor filter's DepthResolution "
                                                "or ColourResolution.");
    return false;
  }

  // depths: 16 bits, empty columns apart from every surface (EncodeDepth)
  vtkDataArray* depthValues = depths->GetPointData()->GetScalars();
  std::vector<unsigned short> codes(static_cast<size_t>(depthValues->GetNumberOfTuples()));
  for (size_t k = 0; k < codes.size(); ++k)
  {
    codes[k] = vtkReliefImpostorFilter::EncodeDepth(
      static_cast<float>(depthValues->GetComponent(static_cast<vtkIdType>(k), 0)));
  }
  for (vtkReliefArrayTexture* texture :
    { this->DepthTexture.Get(), this->PyramidTexture.Get(), this->ColourTexture.Get(),
      this->NormalTexture.Get() })
  {
    texture->SetContext(window);
  }
  using Texture = vtkReliefArrayTexture;
  if (!this->DepthTexture->Create2DArrayFromRaw(depthSize, depthSize, views, GL_R16, GL_RED,
        GL_UNSIGNED_SHORT, 2, codes.data(), Texture::LINEAR))
  {
    vtkErrorMacro("The impostor's depth texture could not be made: lower the impostor "
                  "filter's DepthResolution, or free GPU memory.");
    return false;
  }

  // the search's pyramid of each view, from the depths as the GPU holds them
  if (pyramid)
  {
    std::vector<unsigned short> atlases;
    int atlasSize[2] = { 0, 0 };
    const vtkIdType texels = LayerTexels(depths);
    for (int view = 0; view < views; ++view)
    {
      vtkNew<vtkImageData> field;
      field->SetDimensions(depthSize, depthSize, 1);
      vtkNew<vtkFloatArray> values;
      values->SetNumberOfTuples(texels);
      for (vtkIdType k = 0; k < texels; ++k)
      {
        values->SetValue(
          k, vtkReliefImpostorFilter::DecodeDepth(codes[static_cast<size_t>(view * texels + k)]));
      }
      field->GetPointData()->SetScalars(values);
      vtkNew<vtkMaximumMipmapFilter> builder;
      builder->SetInputData(field);
      builder->Update();
      // the levels above 0, to the right of level 0 in the atlas: the shader takes level
      // 0, each cell's least corner, from the depths themselves
      vtkImageData* atlas = builder->GetOutput();
      const int atlasWidth = atlas->GetDimensions()[0];
      atlasSize[0] = atlasWidth - depthSize;
      atlasSize[1] = atlas->GetDimensions()[1];
      vtkDataArray* nodes = atlas->GetPointData()->GetScalars();
      for (int row = 0; row < atlasSize[1]; ++row)
      {
        for (int column = depthSize; column < atlasWidth; ++column)
        {
          // minima of 16-bit depths: exact as 16 bits again
          const double least = nodes->GetComponent(row * atlasWidth + column, 0);
          atlases.push_back(static_cast<unsigned short>(
            std::lround(std::min(std::max(least, 0.0), 1.0) * 65535.0)));
        }
      }
    }
    if (!this->PyramidTexture->Create2DArrayFromRaw(atlasSize[0], atlasSize[1], views, GL_R16,
          GL_RED, GL_UNSIGNED_SHORT, 2, atlases.data(), Texture::NEAREST))
    {
      vtkErrorMacro("The impostor's pyramid texture could not be made: lower the impostor "
                    "filter's DepthResolution, or search with ExactDDA, which needs none.");
      return false;
    }
  }
  else
  {
    this->PyramidTexture->ReleaseGraphicsResources(window);
  }

  // colours and normals (in the view's frame, NormalFrame, where what the view sees faces
  // +z, the octahedral map's unfolded half), with the texels that saw nothing filled
  // from those around them, so that filtering and mipmaps at outlines blend only what
  // was seen. Colours are compressed where the GL can (S3TC DXT1, half a byte a texel);
  // normals are not: compressed (RGTC2), their coarse mipmaps' errors raised the colour
  // error of a field of small instances by a tenth (0.044 to 0.049 against the mesh)
  vtkDataArray* rgba = colours->GetPointData()->GetScalars();
  vtkDataArray* normals = colours->GetPointData()->GetArray("Normals");
  const size_t layerTexels = static_cast<size_t>(colourSize) * colourSize;
  const size_t colourTexels = static_cast<size_t>(rgba->GetNumberOfTuples());
  std::vector<float> coverage(colourTexels);
  std::vector<float> colour(3 * colourTexels);
  std::vector<float> normal(3 * colourTexels);
  for (int view = 0; view < views; ++view)
  {
    double frame[16];
    NormalFrame(view, views, frame);
    const size_t first = static_cast<size_t>(view) * layerTexels;
    for (size_t k = first; k < first + layerTexels; ++k)
    {
      const vtkIdType id = static_cast<vtkIdType>(k);
      coverage[k] = static_cast<float>(rgba->GetComponent(id, 3) / 255.0);
      double model[3] = { 0.0, 0.0, 0.0 };
      if (normals)
      {
        normals->GetTuple(id, model);
      }
      for (int c = 0; c < 3; ++c)
      {
        colour[3 * k + c] = static_cast<float>(rgba->GetComponent(id, c) / 255.0);
        // the frame's transpose: model axes to the frame
        normal[3 * k + c] = static_cast<float>(
          frame[c] * model[0] + frame[4 + c] * model[1] + frame[8 + c] * model[2]);
      }
    }
    FillEmptyTexels(colour.data() + 3 * first, 3, coverage.data() + first, colourSize);
    FillEmptyTexels(normal.data() + 3 * first, 3, coverage.data() + first, colourSize);
  }
  std::vector<unsigned char> colourBytes(4 * colourTexels, 255);
  std::vector<signed char> octahedral(2 * colourTexels);
  for (size_t k = 0; k < colourTexels; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      colourBytes[4 * k + c] = static_cast<unsigned char>(
        std::lround(255.0 * std::min(std::max(colour[3 * k + c], 0.0f), 1.0f)));
    }
    const double vector[3] = { normal[3 * k], normal[3 * k + 1], normal[3 * k + 2] };
    double encoded[2];
    EncodeOctahedral(vector, encoded);
    for (int c = 0; c < 2; ++c)
    {
      octahedral[2 * k + c] = static_cast<signed char>(std::lround(127.0 * encoded[c]));
    }
  }
  const bool compressed = this->CompressColours && GLEW_EXT_texture_compression_s3tc;
  if (!this->ColourTexture->Create2DArrayFromRaw(colourSize, colourSize, views,
        compressed ? GL_COMPRESSED_RGB_S3TC_DXT1_EXT : GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE,
        compressed ? 0 : 4, colourBytes.data(), Texture::MIPMAPPED) ||
    !this->NormalTexture->Create2DArrayFromRaw(colourSize, colourSize, views, GL_RG8_SNORM,
      GL_RG, GL_BYTE, 2, octahedral.data(), Texture::MIPMAPPED))
  {
    vtkErrorMacro("The impostor's colour textures could not be made: lower the impostor "
                  "filter's ColourResolution, free GPU memory, or turn CompressColours "
                  "off.");
    return false;
  }

  this->Views = views;
  this->DepthSize = depthSize;
  this->ColourSize = colourSize;
  this->ImpostorFilter->GetBox(this->CaptureBox);
  for (int view = 0; view < views; ++view)
  {
    this->ImpostorFilter->GetViewProjection(view, this->Projections[view]);
  }
  return true;
}

double vtkOpenGLReliefImpostorMapper::GetDepthRatio(int view)
{
  const double* box = this->CaptureBox;
  const int axis = view / 2; // views +x, -x, +y, -y, +z, -z; one view: +z
  const int along = this->Views == 1 ? 2 : axis;
  const double depth = box[2 * along + 1] - box[2 * along];
  const double face = std::sqrt((box[2 * ((along + 1) % 3) + 1] - box[2 * ((along + 1) % 3)]) *
    (box[2 * ((along + 2) % 3) + 1] - box[2 * ((along + 2) % 3)]));
  return depth / std::max(face, 1e-300);
}

void vtkOpenGLReliefImpostorMapper::MakeBox()
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(this->CaptureBox);
  cube->Update();
  // its points and outward-wound faces only: no normals or texture coordinates for VTK
  // to read, the impostor's shading is its own
  vtkNew<vtkPolyData> box;
  box->SetPoints(cube->GetOutput()->GetPoints());
  box->SetPolys(cube->GetOutput()->GetPolys());
  this->Box->ShallowCopy(box);
}

//------------------------------------------------------------------------------
bool vtkOpenGLReliefImpostorMapper::ShouldWriteDepth(vtkRenderer* ren, vtkActor* actor)
{
  if (!this->ConservativeDepth)
  {
    return true;
  }
  // a camera inside the box, or whose near plane reaches into it, misses front faces
  double bounds[6];
  actor->GetBounds(bounds);
  vtkCamera* camera = ren->GetActiveCamera();
  double range[2];
  camera->GetClippingRange(range);
  const double* eye = camera->GetPosition();
  const double* along = camera->GetDirectionOfProjection();
  bool inside = false;
  for (double reach : { 0.0, range[0] })
  {
    bool within = true;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double at = eye[axis] + reach * along[axis];
      // grown by the near distance: the near plane's corners reach that far sideways
      within = within && at >= bounds[2 * axis] - range[0] &&
        at <= bounds[2 * axis + 1] + range[0];
    }
    inside = inside || within;
  }
  if (inside && !this->WarnedCameraInside)
  {
    this->WarnedCameraInside = true;
    vtkWarningMacro("The camera is inside the impostor's box, where its front faces cannot "
                    "be drawn: ConservativeDepth is set aside while it is, and true depth "
                    "written.");
  }
  return inside;
}

void vtkOpenGLReliefImpostorMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  // points, wireframe and edges are the mesh's, as VTK draws them, not the box's
  vtkProperty* property = actor->GetProperty();
  const bool surface =
    property->GetRepresentation() == VTK_SURFACE && !property->GetEdgeVisibility();
  const bool impostor = surface && this->UpdateImpostor(ren, actor);
  const bool writeDepth = impostor && this->ShouldWriteDepth(ren, actor);
  if (impostor != this->DrawingImpostor || writeDepth != this->WritingDepth)
  {
    this->DrawingImpostor = impostor;
    this->WritingDepth = writeDepth;
    this->ShaderOptionsTime.Modified();
  }
  if (impostor)
  {
    // the box carries no colours: the captured ones replace the mesh's scalars, which VTK
    // would otherwise map and read by the box's primitives
    this->CurrentInput = this->Box;
    this->SavedScalarVisibility = this->ScalarVisibility;
    this->ScalarVisibility = false;
  }
  this->Superclass::RenderPieceStart(ren, actor);
  if (!impostor)
  {
    return;
  }
  // true depth: the box's back faces, so that every ray through it has a fragment, from
  // anywhere; conservative depth: its front faces
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderer*>(ren)->GetState();
  this->SavedCullFace = state->GetEnumState(GL_CULL_FACE);
  GLint mode = GL_BACK;
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &mode);
  this->SavedCullFaceMode = static_cast<unsigned int>(mode);
  state->vtkglEnable(GL_CULL_FACE);
  const bool mirrored = actor->GetMatrix()->Determinant() < 0.0;
  state->vtkglCullFace(this->WritingDepth != mirrored ? GL_FRONT : GL_BACK);
  this->DepthTexture->Activate();
  this->ColourTexture->Activate();
  this->NormalTexture->Activate();
  if (this->PyramidTexture->GetHandle())
  {
    this->PyramidTexture->Activate();
  }
}

void vtkOpenGLReliefImpostorMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingImpostor)
  {
    this->DepthTexture->Deactivate();
    this->ColourTexture->Deactivate();
    this->NormalTexture->Deactivate();
    if (this->PyramidTexture->GetHandle())
    {
      this->PyramidTexture->Deactivate();
    }
    vtkOpenGLState* state = static_cast<vtkOpenGLRenderer*>(ren)->GetState();
    state->vtkglCullFace(this->SavedCullFaceMode);
    state->SetEnumState(GL_CULL_FACE, this->SavedCullFace);
  }
  this->Superclass::RenderPieceFinish(ren, actor);
  if (this->DrawingImpostor)
  {
    this->ScalarVisibility = this->SavedScalarVisibility;
  }
}

bool vtkOpenGLReliefImpostorMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) ||
    cellBO.ShaderSourceTime < this->ShaderOptionsTime;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefImpostorMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  if (!this->DrawingImpostor || this->LastBoundBO != &this->Primitives[PrimitiveTris] ||
    actor->GetProperty()->GetRepresentation() != VTK_SURFACE)
  {
    this->Superclass::ReplaceShaderValues(shaders, ren, actor);
    return;
  }
  using Rewrites = vtkReliefShaderRewrites;
  const int lightComplexity = this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity;
  std::string vertex = shaders[vtkShader::Vertex]->GetSource();
  std::string fragment = shaders[vtkShader::Fragment]->GetSource();
  bool found = Rewrites::InsertAfter(vertex, Rewrites::VertexDeclarations,
    "out vec4 reliefImpostorVC;\n//VTK::Relief::CameraDec");
  found = Rewrites::InsertBefore(
            vertex, Rewrites::VertexEnd, "reliefImpostorVC = MCVCMatrix * vertexMC;") && found;

  std::string declarations = vtkReliefImpostorFragmentDec;
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::Common", vtkReliefCommon);
  vtkShaderProgram::Substitute(
    declarations, "//VTK::Relief::Search", std::string(vtkReliefSearch) + vtkReliefGridSearch);
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::Frame", vtkReliefImpostorFrame);
  found = Rewrites::InsertAfter(fragment, Rewrites::FragmentSystem,
            "#extension GL_ARB_texture_gather : enable\n") && found;
  found = Rewrites::InsertAfter(fragment, Rewrites::FragmentDeclarations,
            this->GetActiveSearch().GetShaderDefine() + "#define RELIEF_IMPOSTOR_VIEWS " +
              std::to_string(this->Views) + "\n" + declarations) && found;
  found = Rewrites::InsertBefore(
            fragment, Rewrites::FragmentStart, vtkReliefImpostorFragmentImpl) && found;
  // colours from the mesh's scalars replace the property's, as VTK's mapper colours the
  // mesh; white or a texture's, they multiply it
  found = Rewrites::InsertAfter(fragment, Rewrites::FragmentColour,
            "  if (reliefImpostorScalarColours == 1)\n"
            "  {\n"
            "    ambientColor = ambientIntensity * reliefHitColour.rgb;\n"
            "    diffuseColor = diffuseIntensity * reliefHitColour.rgb;\n"
            "  }\n"
            "  else\n"
            "  {\n"
            "    ambientColor *= reliefHitColour.rgb;\n"
            "    diffuseColor *= reliefHitColour.rgb;\n"
            "  }\n") && found;
  if (this->WritingDepth)
  {
    found = Rewrites::Replace(
              fragment, Rewrites::FragmentDepth, "gl_FragDepth = reliefFragDepth;") &&
      found;
  }
  if (lightComplexity > 0)
  {
    found = Rewrites::InsertAfter(fragment, Rewrites::FragmentNormal,
              "  normalVCVSOutput = reliefLitNormalVC;\n"
              "  vertexVC = vec4(reliefHitVC, 1.0);\n") && found;
  }
  found = Rewrites::InsertBefore(fragment, Rewrites::FragmentOutput,
            "if (reliefDisplayMode == 1)\n"
            "  {\n"
            "    float reliefSamples = min(float(reliefHit.samples), 255.0);\n"
            "    gl_FragData[0] = vec4(reliefSamples / 255.0, 0.0, 0.0, 1.0);\n"
            "  }") && found;
  if (!found && !this->WarnedShaderTags)
  {
    this->WarnedShaderTags = true;
    vtkWarningMacro("This VTK's shader templates lack tags the impostor's code goes at "
                    "(vtkReliefShaderRewrites follows VTK 9.1 and 9.2): it may be drawn "
                    "wrong.");
  }
  shaders[vtkShader::Vertex]->SetSource(vertex);
  shaders[vtkShader::Fragment]->SetSource(fragment);

  this->Superclass::ReplaceShaderValues(shaders, ren, actor);

  if (this->WritingDepth)
  {
    // the fragment stands at its hit, not on the box: VTK's code that reads its depth
    // (the shadow-map baker's light depth, depth peeling) reads the hit's
    fragment = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fragment, "gl_FragCoord.z", "reliefFragCoordZ", true);
    vtkShaderProgram::Substitute(fragment, "gl_FragCoord.w", "reliefFragCoordW", true);
    shaders[vtkShader::Fragment]->SetSource(fragment);
  }
  vertex = shaders[vtkShader::Vertex]->GetSource();
  Rewrites::DeclareModelToView(vertex, "//VTK::Relief::CameraDec");
  shaders[vtkShader::Vertex]->SetSource(vertex);
}

void vtkOpenGLReliefImpostorMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* program = cellBO.Program;
  if (!this->DrawingImpostor || !program->IsUniformUsed("reliefImpostorLow"))
  {
    return;
  }
  program->SetUniformi("reliefImpostorDepths", this->DepthTexture->GetTextureUnit());
  program->SetUniformi("reliefImpostorColours", this->ColourTexture->GetTextureUnit());
  program->SetUniformi("reliefImpostorNormals", this->NormalTexture->GetTextureUnit());
  if (this->PyramidTexture->GetHandle())
  {
    program->SetUniformi("reliefImpostorPyramids", this->PyramidTexture->GetTextureUnit());
  }
  const float size[2] = { static_cast<float>(this->DepthSize),
    static_cast<float>(this->DepthSize) };
  program->SetUniform2f("reliefTextureSize", size);
  const vtkReliefSearchMethod& method = this->GetActiveSearch();
  if (method.SetUniforms)
  {
    const int sizes[2] = { this->DepthSize, this->DepthSize };
    method.SetUniforms(program, sizes);
  }
  SetMatrixArrayUniform(program, "reliefImpostorProjections", this->Projections, this->Views);
  float ratios[6];
  for (int view = 0; view < this->Views; ++view)
  {
    ratios[view] = static_cast<float>(this->GetDepthRatio(view));
  }
  program->SetUniform1fv("reliefImpostorDepthRatios", this->Views, ratios);
  double frames[6][16];
  for (int view = 0; view < this->Views; ++view)
  {
    NormalFrame(view, this->Views, frames[view]);
  }
  SetMatrixArrayUniform(program, "reliefImpostorNormalFrames", frames, this->Views);
  const float low[3] = { static_cast<float>(this->CaptureBox[0]),
    static_cast<float>(this->CaptureBox[2]), static_cast<float>(this->CaptureBox[4]) };
  const float high[3] = { static_cast<float>(this->CaptureBox[1]),
    static_cast<float>(this->CaptureBox[3]), static_cast<float>(this->CaptureBox[5]) };
  program->SetUniform3f("reliefImpostorLow", low);
  program->SetUniform3f("reliefImpostorHigh", high);
  program->SetUniformi("reliefLinearSteps", this->LinearSteps);
  program->SetUniformi("reliefBinarySteps", this->BinarySteps);
  program->SetUniformi("reliefDisplayMode", this->DisplayMode);
  program->SetUniformi("reliefImpostorScalarColours", this->ScalarColours ? 1 : 0);
}

void vtkOpenGLReliefImpostorMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* program = cellBO.Program;
  if (!this->DrawingImpostor || !program->IsUniformUsed("reliefImpostorVCMC"))
  {
    return;
  }
  vtkMatrix4x4* worldToViewKey;
  vtkMatrix3x3* normalKey;
  vtkMatrix4x4* viewToDisplayKey;
  vtkMatrix4x4* worldToDisplayKey;
  vtkCamera* camera = ren->GetActiveCamera();
  static_cast<vtkOpenGLCamera*>(camera)->GetKeyMatrices(
    ren, worldToViewKey, normalKey, viewToDisplayKey, worldToDisplayKey);
  program->SetUniformMatrix("reliefVCDCMatrix", viewToDisplayKey);

  // model to view in model units, free of the position VBO's shift and scale
  vtkNew<vtkMatrix4x4> worldToView;
  FromKeyMatrix(worldToViewKey, worldToView);
  vtkNew<vtkMatrix4x4> modelToView;
  vtkMatrix4x4::Multiply4x4(worldToView, actor->GetMatrix(), modelToView);
  vtkNew<vtkMatrix4x4> viewToModel;
  vtkMatrix4x4::Invert(modelToView, viewToModel);
  SetMatrixUniform(program, "reliefImpostorMCVC", modelToView);
  SetMatrixUniform(program, "reliefImpostorVCMC", viewToModel);
  vtkNew<vtkMatrix3x3> normals;
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      // the inverse transpose of the directions' matrix
      normals->SetElement(row, column, viewToModel->GetElement(column, row));
    }
  }
  vtkNew<vtkMatrix3x3> normalsUploaded; // vtkShaderProgram uploads rows as columns
  vtkMatrix3x3::Transpose(normals, normalsUploaded);
  program->SetUniformMatrix("reliefImpostorNormalMatrix", normalsUploaded);

  // the near plane, and a pixel's size for the colours' level
  double range[2];
  camera->GetClippingRange(range);
  program->SetUniformf("reliefNearVC", static_cast<float>(range[0]));
  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  const int across = camera->GetUseHorizontalViewAngle() ? width : height;
  const double spread = camera->GetParallelProjection()
    ? 2.0 * camera->GetParallelScale() / std::max(height, 1)
    : 2.0 * std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle())) /
      std::max(across, 1);
  program->SetUniformf("reliefPixelSpread", static_cast<float>(spread));
  // view units per model unit: the actor's scale
  const double scale = std::cbrt(std::abs(modelToView->Determinant()));
  double meanSide = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    meanSide += (this->CaptureBox[2 * axis + 1] - this->CaptureBox[2 * axis]) / 3.0;
  }
  program->SetUniformf("reliefColourTexelsPerUnit",
    static_cast<float>(this->ColourSize / std::max(meanSide * scale, 1e-30)));
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLReliefImpostorMapper::GetTextureBytes()
{
  return this->DepthTexture->GetBytes() + this->PyramidTexture->GetBytes() +
    this->ColourTexture->GetBytes() + this->NormalTexture->GetBytes();
}

void vtkOpenGLReliefImpostorMapper::ReleaseTextures(vtkWindow* window)
{
  this->DepthTexture->ReleaseGraphicsResources(window);
  this->PyramidTexture->ReleaseGraphicsResources(window);
  this->ColourTexture->ReleaseGraphicsResources(window);
  this->NormalTexture->ReleaseGraphicsResources(window);
  this->UploadedCaptureTime = 0;
  this->UploadedWindow = nullptr;
  this->UploadedPyramid = false;
}

void vtkOpenGLReliefImpostorMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ReleaseTextures(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLReliefImpostorMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SearchMethod: " << Mapper::GetSearchMethodAsString(this->SearchMethod) << "\n";
  os << indent
     << "ActiveSearchMethod: " << Mapper::GetSearchMethodAsString(this->ActiveSearchMethod)
     << "\n";
  os << indent << "LinearSteps: " << this->LinearSteps << "\n";
  os << indent << "BinarySteps: " << this->BinarySteps << "\n";
  os << indent << "ConservativeDepth: " << this->ConservativeDepth << "\n";
  os << indent << "AutomaticResolution: " << this->AutomaticResolution << "\n";
  os << indent << "CompressColours: " << this->CompressColours << "\n";
  os << indent << "DisplayMode: " << (this->DisplayMode == SAMPLE_COUNT ? "SampleCount" : "Shaded")
     << "\n";
  os << indent << "DrawingImpostor: " << this->DrawingImpostor << "\n";
  os << indent << "Views: " << this->Views << "\n";
  os << indent << "TextureBytes: " << this->GetTextureBytes() << "\n";
  os << indent << "ImpostorFilter:\n";
  this->ImpostorFilter->PrintSelf(os, indent.GetNextIndent());
}

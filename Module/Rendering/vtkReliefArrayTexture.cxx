#include "vtkReliefArrayTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkReliefArrayTexture);

vtkReliefArrayTexture::vtkReliefArrayTexture()
{
  this->AutoParameters = 0;
}

bool vtkReliefArrayTexture::Create2DArrayFromRaw(unsigned int width, unsigned int height,
  unsigned int layers, unsigned int internalFormat, unsigned int format, unsigned int type,
  int bytesPerTexel, const void* data, int filtering)
{
  const bool mipmapped = filtering == MIPMAPPED;
  if (!this->Context)
  {
    vtkErrorMacro("No context: call SetContext() with the render window first.");
    return false;
  }
  vtkOpenGLClearErrorMacro();
  this->Target = GL_TEXTURE_2D_ARRAY;
  this->InternalFormat = internalFormat;
  this->Format = format;
  this->Type = type;
  this->Width = width;
  this->Height = height;
  this->Depth = layers;
  this->NumberOfDimensions = 2;
  this->Context->ActivateTexture(this);
  this->CreateTexture();
  this->Bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage3D(this->Target, 0, static_cast<GLint>(internalFormat), static_cast<GLsizei>(width),
    static_cast<GLsizei>(height), static_cast<GLsizei>(layers), 0, format, type, data);
  const GLint magnification = filtering == NEAREST ? GL_NEAREST : GL_LINEAR;
  const GLint minification = filtering == MIPMAPPED ? GL_LINEAR_MIPMAP_LINEAR : magnification;
  glTexParameteri(this->Target, GL_TEXTURE_MIN_FILTER, minification);
  glTexParameteri(this->Target, GL_TEXTURE_MAG_FILTER, magnification);
  glTexParameteri(this->Target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(this->Target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(this->Target, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(this->Target, GL_TEXTURE_MAX_LEVEL, mipmapped ? 1000 : 0);
  if (mipmapped)
  {
    glGenerateMipmap(this->Target);
  }
  vtkIdType texels = 0;
  vtkIdType compressedBytes = 0;
  for (unsigned int level = 0; level == 0 || (mipmapped && (width >> level | height >> level));
       ++level)
  {
    texels += static_cast<vtkIdType>(std::max(width >> level, 1u)) * std::max(height >> level, 1u);
    GLint levelBytes = 0;
    if (bytesPerTexel == 0)
    {
      glGetTexLevelParameteriv(
        this->Target, static_cast<GLint>(level), GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &levelBytes);
    }
    compressedBytes += levelBytes;
  }
  this->Deactivate();
  this->Bytes = bytesPerTexel == 0 ? compressedBytes : texels * layers * bytesPerTexel;
  return glGetError() == GL_NO_ERROR;
}

void vtkReliefArrayTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layers: " << this->Depth << "\n";
  os << indent << "Bytes: " << this->GetBytes() << "\n";
}

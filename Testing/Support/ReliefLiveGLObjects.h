#ifndef ReliefLiveGLObjects_h
#define ReliefLiveGLObjects_h

#include "vtk_glew.h"

// GL objects alive in the current context, counted by name: what the leak checks of the
// regression tests compare before and after. Header only: the tests link GL themselves.
namespace ReliefLiveGLObjects
{
inline int Programs()
{
  int count = 0;
  for (GLuint name = 1; name < 4096; ++name)
  {
    count += glIsProgram(name) ? 1 : 0;
  }
  return count;
}

inline int Textures()
{
  int count = 0;
  for (GLuint name = 1; name < 4096; ++name)
  {
    count += glIsTexture(name) ? 1 : 0;
  }
  return count;
}
}

#endif

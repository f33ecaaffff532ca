#include "PsiSamplesPassed.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides

PsiSamplesPassed::~PsiSamplesPassed() = default; // the query is the context's (Release)

void PsiSamplesPassed::Begin(bool on)
{
  if (!on)
  {
    return;
  }
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  this->Counting = true;
}

void PsiSamplesPassed::End()
{
  if (!this->Counting)
  {
    return;
  }
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samples = 0;
  glGetQueryObjectui64v(this->Query, GL_QUERY_RESULT, &samples);
  this->Total += samples;
  this->Counting = false;
}

void PsiSamplesPassed::ReleaseGraphicsResources()
{
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
  }
  this->Query = 0;
  this->Counting = false;
}

#include "PsiSamplesPassed.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides

PsiSamplesPassed::~PsiSamplesPassed() = default; // the query is the context's (Release)

void PsiSamplesPassed::Begin()
{
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  this->Counting = true;
  this->Pending = false;
}

void PsiSamplesPassed::End()
{
  if (this->Counting)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    this->Counting = false;
    this->Pending = true;
  }
}

uint64_t PsiSamplesPassed::Take()
{
  GLuint64 samples = 0;
  if (this->Pending)
  {
    glGetQueryObjectui64v(this->Query, GL_QUERY_RESULT, &samples);
    this->Pending = false;
  }
  return samples;
}

void PsiSamplesPassed::ReleaseGraphicsResources()
{
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
  }
  this->Query = 0;
  this->Counting = this->Pending = false;
}

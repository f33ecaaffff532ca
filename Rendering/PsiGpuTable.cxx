#include "PsiGpuTable.h"

void psi::UpdateTables(
  const std::vector<PsiGpuTable*>& tables, vtkOpenGLRenderWindow* renWin, const PsiTableSources& in)
{
  for (PsiGpuTable* t : tables)
  {
    if (t->NeedsUpdate(in))
    {
      t->Update(renWin, in);
    }
  }
}

void psi::ActivateTables(const std::vector<PsiGpuTable*>& tables, vtkShaderProgram* program)
{
  for (PsiGpuTable* t : tables)
  {
    t->Activate(program);
  }
}

void psi::DeactivateTables(const std::vector<PsiGpuTable*>& tables)
{
  for (PsiGpuTable* t : tables)
  {
    t->Deactivate();
  }
}

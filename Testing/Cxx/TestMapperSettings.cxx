// The mapper holds the one settings type (psi::Settings, Core/PsiSettings.h): its integration
// method is clamped to the method table and named from it, and its default is the settings'
// (which PsiCore.Settings and PsiCore.IntegrationMethods check against the XML). GL-free.
#include "PsiIntegrationMethods.h"
#include "PsiSettings.h"
#include "PsiTestCheck.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkNew.h"

#include <string>

namespace
{
// The mapper takes the table's values, clamped, and names them from the table.
void CheckIntegrationMethod()
{
  const auto& table = psi::IntegrationMethodTable();
  vtkNew<vtkPsiVolumeMapper> mapper;
  const int last = psi::NumberOfIntegrationMethods() - 1;
  mapper->SetIntegrationMethod(-3);
  PSI_CHECK(mapper->GetIntegrationMethod() == 0, "clamped below");
  mapper->SetIntegrationMethod(last + 5);
  PSI_CHECK(mapper->GetIntegrationMethod() == last, "clamped above");
  PSI_CHECK(std::string(vtkPsiVolumeMapper::GetIntegrationMethodName(last)) == table[last].Name &&
      std::string(vtkPsiVolumeMapper::GetIntegrationMethodName(last + 1)) == "Unknown",
    "mapper names");
  const int mapperDefault = vtkNew<vtkPsiVolumeMapper>()->GetIntegrationMethod();
  const int settingsDefault = static_cast<int>(psi::Settings().IntegrationMethod);
  PSI_CHECK(mapperDefault == settingsDefault, "mapper default %d, settings default %d",
    mapperDefault, settingsDefault);
}
} // namespace

int main()
{
  CheckIntegrationMethod();
  return psitest::Report("TestMapperSettings");
}

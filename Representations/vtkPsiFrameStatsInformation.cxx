#include "vtkPsiFrameStatsInformation.h"

#include "vtkClientServerStream.h"
#include "vtkObjectFactory.h"
#include "vtkPsiVolumeRepresentation.h"

#include <algorithm>

vtkStandardNewMacro(vtkPsiFrameStatsInformation);

vtkPsiFrameStatsInformation::vtkPsiFrameStatsInformation()
{
  this->RootOnly = 0;
}

vtkPsiFrameStatsInformation::~vtkPsiFrameStatsInformation() = default;

void vtkPsiFrameStatsInformation::CopyFromObject(vtkObject* object)
{
  auto repr = vtkPsiVolumeRepresentation::SafeDownCast(object);
  if (!repr)
  {
    return;
  }
  this->NumberOfTetrahedra = repr->GetNumberOfTetrahedra();
  this->NumberOfSkippedCells = repr->GetNumberOfSkippedCells();
  this->LastSortCycles = repr->GetLastSortCycles();
  this->LastRenderSeconds = repr->GetLastRenderSeconds();
  this->LastSortSeconds = repr->GetLastSortSeconds();
  this->LastPreIntegrationSeconds = repr->GetLastPreIntegrationSeconds();
}

void vtkPsiFrameStatsInformation::AddInformation(vtkPVInformation* other)
{
  auto stats = vtkPsiFrameStatsInformation::SafeDownCast(other);
  if (!stats)
  {
    return;
  }
  this->NumberOfTetrahedra += stats->NumberOfTetrahedra;
  this->NumberOfSkippedCells += stats->NumberOfSkippedCells;
  this->LastSortCycles += stats->LastSortCycles;
  this->LastRenderSeconds = std::max(this->LastRenderSeconds, stats->LastRenderSeconds);
  this->LastSortSeconds = std::max(this->LastSortSeconds, stats->LastSortSeconds);
  this->LastPreIntegrationSeconds =
    std::max(this->LastPreIntegrationSeconds, stats->LastPreIntegrationSeconds);
}

void vtkPsiFrameStatsInformation::CopyToStream(vtkClientServerStream* stream)
{
  stream->Reset();
  *stream << vtkClientServerStream::Reply << static_cast<long long>(this->NumberOfTetrahedra)
          << static_cast<long long>(this->NumberOfSkippedCells)
          << static_cast<long long>(this->LastSortCycles) << this->LastRenderSeconds
          << this->LastSortSeconds << this->LastPreIntegrationSeconds << vtkClientServerStream::End;
}

void vtkPsiFrameStatsInformation::CopyFromStream(const vtkClientServerStream* stream)
{
  long long counts[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; ++i)
  {
    stream->GetArgument(0, i, &counts[i]);
  }
  this->NumberOfTetrahedra = static_cast<vtkIdType>(counts[0]);
  this->NumberOfSkippedCells = static_cast<vtkIdType>(counts[1]);
  this->LastSortCycles = static_cast<vtkIdType>(counts[2]);
  stream->GetArgument(0, 3, &this->LastRenderSeconds);
  stream->GetArgument(0, 4, &this->LastSortSeconds);
  stream->GetArgument(0, 5, &this->LastPreIntegrationSeconds);
}

void vtkPsiFrameStatsInformation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
  os << indent << "LastSortCycles: " << this->LastSortCycles << "\n";
  os << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
  os << indent << "LastSortSeconds: " << this->LastSortSeconds << "\n";
  os << indent << "LastPreIntegrationSeconds: " << this->LastPreIntegrationSeconds << "\n";
}

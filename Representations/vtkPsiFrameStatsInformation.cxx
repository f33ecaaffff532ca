#include "vtkPsiFrameStatsInformation.h"

#include "vtkClientServerStream.h"
#include "vtkObjectFactory.h"
#include "vtkPsiVolumeRepresentation.h"

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
  this->Stats = repr->GetFrameStats();
}

void vtkPsiFrameStatsInformation::AddInformation(vtkPVInformation* other)
{
  auto stats = vtkPsiFrameStatsInformation::SafeDownCast(other);
  if (!stats)
  {
    return;
  }
  this->Stats.Add(stats->Stats);
}

void vtkPsiFrameStatsInformation::CopyToStream(vtkClientServerStream* stream)
{
  stream->Reset();
  *stream << vtkClientServerStream::Reply << static_cast<long long>(this->Stats.NumberOfTetrahedra)
          << static_cast<long long>(this->Stats.NumberOfSkippedCells)
          << static_cast<long long>(this->Stats.LastSortCycles) << this->Stats.LastRenderSeconds
          << this->Stats.LastSortSeconds << this->Stats.LastPreIntegrationSeconds
          << static_cast<long long>(this->Stats.IntermixedVolumes)
          << static_cast<long long>(this->Stats.IntermixedTetrahedra) << this->Stats.DrawWay.c_str()
          << vtkClientServerStream::End;
}

void vtkPsiFrameStatsInformation::CopyFromStream(const vtkClientServerStream* stream)
{
  long long counts[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; ++i)
  {
    stream->GetArgument(0, i, &counts[i]);
  }
  this->Stats.NumberOfTetrahedra = static_cast<vtkIdType>(counts[0]);
  this->Stats.NumberOfSkippedCells = static_cast<vtkIdType>(counts[1]);
  this->Stats.LastSortCycles = static_cast<vtkIdType>(counts[2]);
  stream->GetArgument(0, 3, &this->Stats.LastRenderSeconds);
  stream->GetArgument(0, 4, &this->Stats.LastSortSeconds);
  stream->GetArgument(0, 5, &this->Stats.LastPreIntegrationSeconds);
  long long intermixed[2] = { 0, 0 };
  stream->GetArgument(0, 6, &intermixed[0]);
  stream->GetArgument(0, 7, &intermixed[1]);
  this->Stats.IntermixedVolumes = intermixed[0];
  this->Stats.IntermixedTetrahedra = intermixed[1];
  const char* way = nullptr;
  this->Stats.DrawWay = stream->GetArgument(0, 8, &way) && way ? way : "";
}

void vtkPsiFrameStatsInformation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTetrahedra: " << this->Stats.NumberOfTetrahedra << "\n";
  os << indent << "NumberOfSkippedCells: " << this->Stats.NumberOfSkippedCells << "\n";
  os << indent << "LastSortCycles: " << this->Stats.LastSortCycles << "\n";
  os << indent << "LastRenderSeconds: " << this->Stats.LastRenderSeconds << "\n";
  os << indent << "LastSortSeconds: " << this->Stats.LastSortSeconds << "\n";
  os << indent << "LastPreIntegrationSeconds: " << this->Stats.LastPreIntegrationSeconds << "\n";
  os << indent << "IntermixedVolumes: " << this->Stats.IntermixedVolumes << "\n";
  os << indent << "IntermixedTetrahedra: " << this->Stats.IntermixedTetrahedra << "\n";
  os << indent << "DrawWay: " << this->Stats.DrawWay << "\n";
}

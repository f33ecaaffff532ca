#include "pqPsiFrameStatsWidget.h"

#include "pqApplicationCore.h"
#include "pqRepresentation.h"
#include "pqServerManagerModel.h"
#include "pqTimer.h"
#include "pqView.h"
#include "vtkNew.h"
#include "vtkPVSession.h"
#include "vtkPsiFrameStatsInformation.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMSession.h"

#include <QApplication>
#include <QByteArray>
#include <QLabel>
#include <QLocale>
#include <QRegularExpression>
#include <QShowEvent>
#include <QStringList>
#include <QVBoxLayout>

namespace
{
// A read-out property of the 'Psi Volume' sub-proxy, as exposed on the representation proxy.
constexpr const char* TetrahedraName = "NumberOfTetrahedra";

QString milliseconds(double seconds)
{
  const double ms = 1000.0 * seconds;
  return QString::number(ms, 'f', ms < 10.0 ? 2 : 1);
}

QString count(long long n)
{
  return QLocale(QLocale::English).toString(n);
}

QString tooltip(const pqPsiFrameStatsWidget::Readout& stats)
{
  QString text = pqPsiFrameStatsWidget::tr(
    "The last frame of 'Psi Volume' in this view: CPU time of the render call (sorting, uploads, "
    "draw submission) and of its visibility sort, tetrahedra drawn, cells not drawn (not "
    "tetrahedra, or NaN/Inf scalars) and, for MPVONC, visibility cycles broken. Updated after "
    "every render.");
  if (stats.Stats.LastPreIntegrationSeconds > 0)
  {
    text += pqPsiFrameStatsWidget::tr("\nLast full pre-integration table build: %1 ms.")
              .arg(milliseconds(stats.Stats.LastPreIntegrationSeconds));
  }
  return text;
}
}

//-----------------------------------------------------------------------------
pqPsiFrameStatsWidget::pqPsiFrameStatsWidget(
  vtkSMProxy* smproxy, vtkSMPropertyGroup* vtkNotUsed(smgroup), QWidget* parentObject)
  : Superclass(smproxy, parentObject)
  , Label(new QLabel(this))
  , RefreshTimer(new pqTimer(this))
{
  this->Label->setObjectName("FrameStats");
  this->Label->setWordWrap(true);
  this->Label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  this->Label->setToolTip(tooltip(Readout()));
  auto layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(this->Label);

  // Read once the render call has returned (and once for renders queued together). pqTimer makes
  // GUI test playback wait for it.
  this->RefreshTimer->setSingleShot(true);
  this->RefreshTimer->setInterval(0);
  this->connect(this->RefreshTimer, SIGNAL(timeout()), SLOT(refresh()));

  // The view that draws this representation (not necessarily the active view).
  pqServerManagerModel* smmodel = pqApplicationCore::instance()->getServerManagerModel();
  if (auto repr = smmodel->findItem<pqRepresentation*>(smproxy))
  {
    this->connect(repr, SIGNAL(visibilityChanged(bool)), SLOT(scheduleRefresh()));
    if (repr->getView())
    {
      this->ViewFromRepresentation = true;
      this->watchView(repr->getView());
    }
  }

  this->Label->setText(formatReadout(Readout()));
  this->scheduleRefresh();
}

//-----------------------------------------------------------------------------
pqPsiFrameStatsWidget::~pqPsiFrameStatsWidget() = default;

//-----------------------------------------------------------------------------
void pqPsiFrameStatsWidget::setView(pqView* view)
{
  this->Superclass::setView(view);
  if (!this->ViewFromRepresentation)
  {
    this->watchView(view);
  }
}

//-----------------------------------------------------------------------------
void pqPsiFrameStatsWidget::watchView(pqView* view)
{
  if (this->WatchedView == view)
  {
    return;
  }
  if (this->WatchedView)
  {
    this->WatchedView->disconnect(this);
  }
  this->WatchedView = view;
  if (view)
  {
    this->connect(view, SIGNAL(endRender()), SLOT(scheduleRefresh()));
  }
  this->scheduleRefresh();
}

//-----------------------------------------------------------------------------
void pqPsiFrameStatsWidget::scheduleRefresh()
{
  this->RefreshTimer->start();
}

//-----------------------------------------------------------------------------
void pqPsiFrameStatsWidget::showEvent(QShowEvent* event)
{
  this->Superclass::showEvent(event);
  this->scheduleRefresh();
}

//-----------------------------------------------------------------------------
void pqPsiFrameStatsWidget::refresh()
{
  // Hidden (another representation type is shown): nothing to read, and no server round trip.
  if (!this->isVisible())
  {
    return;
  }
  const Readout stats = this->readStats();
  this->Label->setText(formatReadout(stats));
  this->Label->setToolTip(tooltip(stats));
}

//-----------------------------------------------------------------------------
pqPsiFrameStatsWidget::Readout pqPsiFrameStatsWidget::readStats()
{
  Readout stats;
  vtkSMProxy* smproxy = this->proxy();
  vtkSMProperty* tetrahedra = smproxy ? smproxy->GetProperty(TetrahedraName) : nullptr;
  if (!tetrahedra)
  {
    return stats;
  }
  if (smproxy->GetProperty("Visibility") &&
    vtkSMPropertyHelper(smproxy, "Visibility").GetAsInt() == 0)
  {
    stats.Hidden = true;
    return stats;
  }

  // The 'Psi Volume' sub-proxy of the representation, which owns the read-out properties.
  vtkSMProxy* owner = tetrahedra->GetParent() ? tetrahedra->GetParent() : smproxy;
  // Gathered from the processes that render: this process in the builtin session, the server's
  // ranks in client/server (volume representations always render on the server there).
  vtkNew<vtkPsiFrameStatsInformation> info;
  owner->GetSession()->GatherInformation(vtkPVSession::RENDER_SERVER, info, owner->GetGlobalID());
  stats.Stats = info->GetFrameStats();
  const psi::FrameStats& s = stats.Stats;
  stats.Drawn = s.LastRenderSeconds > 0 || s.NumberOfTetrahedra > 0 || s.NumberOfSkippedCells > 0;
  return stats;
}

//-----------------------------------------------------------------------------
QString pqPsiFrameStatsWidget::formatReadout(const Readout& stats)
{
  if (stats.Hidden)
  {
    return tr("last frame: not drawn (representation hidden)");
  }
  if (!stats.Drawn)
  {
    return tr("last frame: not rendered yet");
  }
  QString text =
    tr("last frame: %1 ms (sort %2 ms), %3 tetrahedra, %4 cells skipped")
      .arg(milliseconds(stats.Stats.LastRenderSeconds), milliseconds(stats.Stats.LastSortSeconds),
        count(stats.Stats.NumberOfTetrahedra), count(stats.Stats.NumberOfSkippedCells));
  if (stats.Stats.LastSortCycles > 0)
  {
    text += tr(", %1 sort cycles").arg(count(stats.Stats.LastSortCycles));
  }
  if (stats.Stats.IntermixedVolumes > 1) // the times are the combined draw's
  {
    // one draw, one set of settings: the first volume's (in the view's order) apply to all
    const qlonglong others = stats.Stats.IntermixedVolumes - 1;
    text += tr("; drawn intermixed with %1 other %2 (%3 tetrahedra in all, the settings of the "
               "view's first)")
              .arg(others)
              .arg(others == 1 ? tr("volume") : tr("volumes"))
              .arg(count(stats.Stats.IntermixedTetrahedra));
  }
  if (!stats.Stats.DrawWay.empty()) // "back to front, ... (chosen by measurement of 4 ways)"
  {
    text += tr("; drawn %1").arg(QString::fromStdString(stats.Stats.DrawWay));
  }
  return text;
}

//-----------------------------------------------------------------------------
QString pqPsiFrameStatsWidget::readout() const
{
  return this->Label->text();
}

//-----------------------------------------------------------------------------
qlonglong pqPsiFrameStatsWidget::shownTetrahedra() const
{
  static const QRegularExpression pattern("([0-9,]+) tetrahedra");
  const QRegularExpressionMatch match = pattern.match(this->Label->text());
  return match.hasMatch() ? match.captured(1).remove(',').toLongLong() : -1;
}

//-----------------------------------------------------------------------------
bool pqPsiFrameStatsWidget::showsFrameTime() const
{
  static const QRegularExpression pattern(
    "^last frame: ([0-9]+\\.[0-9]+) ms \\(sort ([0-9]+\\.[0-9]+) ms\\)");
  const QRegularExpressionMatch match = pattern.match(this->Label->text());
  return match.hasMatch() && match.captured(1).toDouble() > 0;
}

//-----------------------------------------------------------------------------
const char* pqPsiFrameStatsReadouts()
{
  static QByteArray text;
  QStringList shown;
  for (QWidget* widget : QApplication::allWidgets())
  {
    auto readout = qobject_cast<pqPsiFrameStatsWidget*>(widget);
    if (readout && readout->isVisible())
    {
      shown << readout->readout();
    }
  }
  text = shown.join('\n').toUtf8();
  return text.constData();
}

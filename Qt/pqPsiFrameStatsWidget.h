/**
 * @class   pqPsiFrameStatsWidget
 * @brief   Properties-panel read-out of the last 'Psi Volume' frame.
 *
 * Group widget (`panel_widget="psi_frame_stats"` on the "Psi Volume Last Frame" property group)
 * showing one line: "last frame: X ms (sort Y ms), N tetrahedra, M cells skipped[, K sort
 * cycles]". ParaView 5.11 gives the group's information-only IdType properties no widget and
 * never re-reads information properties after a render, so this widget reads the values itself
 * after every render of the representation's view (pqView::endRender, then a zero-delay timer:
 * the read happens once the render call has returned, once for renders queued together).
 *
 * Where the numbers come from: vtkPsiFrameStatsInformation, gathered from the processes that
 * render (this process in the builtin session; the server, summed over its MPI ranks, in
 * client/server, where ParaView 5.11 always renders volume representations on the server).
 * Pulling the information properties would not do in client/server: ParaView pulls them from the
 * client's copy of the representation, which draws nothing there.
 *
 * The Qt properties `shownTetrahedra` and `showsFrameTime` parse the text the label shows, for
 * GUI tests (QtTesting's pqcheck compares exact strings, and frame times vary). The text itself
 * reaches the client's Python shell through pqPsiFrameStatsReadouts() below: that Python has no
 * Qt bindings, and a pqcheck cannot compare the label with values known only while the test runs.
 */
#ifndef pqPsiFrameStatsWidget_h
#define pqPsiFrameStatsWidget_h

#include "PsiFrameStats.h"

#include "pqPropertyWidget.h"

#include <QPointer>
#include <QString>

class QLabel;
class pqTimer;
class pqView;
class vtkSMPropertyGroup;

class pqPsiFrameStatsWidget : public pqPropertyWidget
{
  Q_OBJECT
  Q_PROPERTY(QString readout READ readout)
  Q_PROPERTY(qlonglong shownTetrahedra READ shownTetrahedra)
  Q_PROPERTY(bool showsFrameTime READ showsFrameTime)
  typedef pqPropertyWidget Superclass;

public:
  pqPsiFrameStatsWidget(vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqPsiFrameStatsWidget() override;

  /// The last frame as the mapper reports it (psi::FrameStats, gathered over the processes),
  /// and whether there is one to show.
  struct Readout
  {
    bool Drawn = false; // false: hidden, or not rendered yet
    bool Hidden = false;
    psi::FrameStats Stats;
  };

  /// The line shown for `stats`.
  static QString formatReadout(const Readout& stats);

  /// The text shown now.
  QString readout() const;
  /// N of "N tetrahedra" in the text shown now; -1 if the text has no such part.
  qlonglong shownTetrahedra() const;
  /// True if the text shown now starts with "last frame: X ms (sort Y ms)" and X > 0.
  bool showsFrameTime() const;

public Q_SLOTS:
  /// Re-reads the values now and rewrites the line.
  void refresh();

  /// Used when the representation's own view cannot be found.
  void setView(pqView* view) override;

protected:
  void showEvent(QShowEvent* event) override;

private Q_SLOTS:
  void scheduleRefresh();

private:
  Q_DISABLE_COPY(pqPsiFrameStatsWidget)

  void watchView(pqView* view);
  Readout readStats();

  QLabel* Label;
  pqTimer* RefreshTimer;
  QPointer<pqView> WatchedView;
  bool ViewFromRepresentation = false;
};

/// For GUI tests that compare the read-out with the representation's information properties from
/// the client's Python shell (ctypes, Testing/XML/PsiGUICheck.py): the text of every read-out
/// widget shown now, one line each (UTF-8; "" when none is shown). The pointer stays valid until
/// the next call. Call it on the GUI thread, where the shell runs.
extern "C" Q_DECL_EXPORT const char* pqPsiFrameStatsReadouts();

#endif

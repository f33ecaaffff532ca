#include "pqPsiAccuracyReportActions.h"

#include "pqPVApplicationCore.h"

#include <QAction>
#include <QByteArray>
#include <QtDebug>

#ifdef PSI_GUI_PYTHON
#include "pqPythonManager.h"
#endif

//-----------------------------------------------------------------------------
pqPsiAccuracyReportActions::pqPsiAccuracyReportActions(QObject* parentObject)
  : QActionGroup(parentObject)
{
  auto action = new QAction(tr("Accuracy report"), this);
  action->setObjectName("actionPsiAccuracyReport");
  action->setToolTip(tr("Accuracy report: every method of 'Psi Volume' and ParaView's volume "
                        "mappers on the active source and view, timed and measured against the "
                        "exact reference"));
  action->setStatusTip(action->toolTip());
  QObject::connect(action, &QAction::triggered, &pqPsiAccuracyReportActions::runReport);
  this->addAction(action);
}

//-----------------------------------------------------------------------------
const char* pqPsiAccuracyReportActions::pythonCode()
{
  // __import__ binds no name in the user's namespace, where ParaView runs the code; run_report
  // binds none there either (its tables run no script)
  return "__import__('psivolume.gui').gui.run_report()\n";
}

//-----------------------------------------------------------------------------
void pqPsiAccuracyReportActions::runReport()
{
#ifdef PSI_GUI_PYTHON
  auto core = pqPVApplicationCore::instance();
  pqPythonManager* python = core ? core->pythonManager() : nullptr;
  if (python)
  {
    python->executeCode(QByteArray(pythonCode()));
    return;
  }
#endif
  qWarning() << "Accuracy report: needs ParaView's Python (Python/psivolume/gui.py)";
}

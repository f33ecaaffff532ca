/**
 * @class   pqPsiAccuracyReportActions
 * @brief   The action 'Accuracy report' in the toolbar 'Psi Volume'.
 *
 * Runs the accuracy report (Python/psivolume/accuracy.py) on the active source and view in the
 * GUI's Python, through psivolume.gui.run_report(): ParaView's progress bar follows it, and its
 * rows appear in a layout of their own (a spreadsheet view and a point chart of error against
 * time). Its output and any Python error go to the Output Messages window. The options it runs
 * with are psivolume.gui.OPTIONS (editable from the Python shell).
 *
 * pqPsiAccuracyReportMenuActions puts the same action in the Tools menu. Without ParaView's
 * Python the action says the report needs it.
 */
#ifndef pqPsiAccuracyReportActions_h
#define pqPsiAccuracyReportActions_h

#include <QActionGroup>

class pqPsiAccuracyReportActions : public QActionGroup
{
  Q_OBJECT

public:
  explicit pqPsiAccuracyReportActions(QObject* parent);

  /// The Python the action runs.
  static const char* pythonCode();

  /// Runs pythonCode() in the GUI's Python (pqPythonManager::executeCode, as macros run).
  static void runReport();
};

#endif

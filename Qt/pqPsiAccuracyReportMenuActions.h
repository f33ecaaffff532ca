/**
 * @class   pqPsiAccuracyReportMenuActions
 * @brief   The action 'Accuracy report' of pqPsiAccuracyReportActions, in the Tools menu.
 *
 * ParaView places a plugin's action group in one toolbar or one menu; this second group puts
 * the same action in the Tools menu.
 */
#ifndef pqPsiAccuracyReportMenuActions_h
#define pqPsiAccuracyReportMenuActions_h

#include "pqPsiAccuracyReportActions.h"

class pqPsiAccuracyReportMenuActions : public pqPsiAccuracyReportActions
{
public:
  explicit pqPsiAccuracyReportMenuActions(QObject* parent)
    : pqPsiAccuracyReportActions(parent)
  {
  }
};

#endif

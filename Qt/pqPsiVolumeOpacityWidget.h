/**
 * @class   pqPsiVolumeOpacityWidget
 * @brief   The 'Psi Volume Opacity' group: edits the opacity properties of 'Volume' itself.
 *
 * Group widget (`panel_widget="psi_volume_opacity"` on the "Psi Volume Opacity" property group,
 * XML/PsiVolumeRepresentation.xml). The group lists the 'Psi Volume' sub-proxy's copies of
 * ScalarOpacityFunction and ScalarOpacityUnitDistance (exposed as PsiScalarOpacityFunction and
 * PsiScalarOpacityUnitDistance), because ParaView 5.11 shows its own "Volume Rendering" group
 * only for 'Volume' and 'NVIDIA IndeX'. Those copies are the OUTPUT of the one-way property link
 * that <ShareProperties subproxy="VolumeRepresentation"> sets up (vtkSMProxy::
 * SetupSharedProperties): a value typed into them changes 'Psi Volume' only, the
 * VolumeRepresentation's property keeps its old value, and on state load that old value is pushed
 * through the link over the saved copy.
 *
 * So this widget shows, for each property of the group, ParaView's standard widget
 * (pqProxyWidget::createWidgetForProperty) for the representation proxy's OWN property of the
 * same XML name (the exposed VolumeRepresentation property, the link INPUT: what pvpython's
 * `d.ScalarOpacityUnitDistance` sets). Edits reach 'Psi Volume' through the link and are saved
 * where state loading reads them. A property without a standard widget (ScalarOpacityFunction, a
 * proxy property set with the color map) is left out, as pqProxyWidget would.
 *
 * Each child is named after the group's exposed name (e.g. "PsiScalarOpacityUnitDistance"),
 * labelled and tool-tipped like a property row of the panel; changeAvailable()/changeFinished()
 * and apply()/reset() are forwarded, so both auto-apply and the Apply button work.
 */
#ifndef pqPsiVolumeOpacityWidget_h
#define pqPsiVolumeOpacityWidget_h

#include "pqPropertyWidget.h"

#include <QList>
#include <QPointer>

class vtkSMPropertyGroup;

class pqPsiVolumeOpacityWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;

public:
  pqPsiVolumeOpacityWidget(vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqPsiVolumeOpacityWidget() override;

  void apply() override;
  void reset() override;
  void select() override;
  void deselect() override;
  void updateWidget(bool showing_advanced_properties) override;

public Q_SLOTS:
  void setView(pqView* view) override;

private:
  Q_DISABLE_COPY(pqPsiVolumeOpacityWidget)

  QList<QPointer<pqPropertyWidget>> Children;
};

#endif

#include "pqPsiVolumeOpacityWidget.h"

#include "pqPropertiesPanel.h"
#include "pqProxyWidget.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyGroup.h"
#include "vtkSMProxy.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QLabel>

#include <cstring>

//-----------------------------------------------------------------------------
pqPsiVolumeOpacityWidget::pqPsiVolumeOpacityWidget(
  vtkSMProxy* smproxy, vtkSMPropertyGroup* smgroup, QWidget* parentObject)
  : Superclass(smproxy, parentObject)
{
  // changeFinished() comes from the children, after their changeAvailable().
  this->setChangeAvailableAsChangeFinished(false);

  auto layout = new QGridLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setHorizontalSpacing(pqPropertiesPanel::suggestedHorizontalSpacing());
  layout->setVerticalSpacing(pqPropertiesPanel::suggestedVerticalSpacing());
  layout->setColumnStretch(1, 1);

  for (unsigned int i = 0; smgroup && i < smgroup->GetNumberOfProperties(); ++i)
  {
    vtkSMProperty* copy = smgroup->GetProperty(i); // the 'Psi Volume' sub-proxy's property
    if (!copy || !copy->GetXMLName())
    {
      continue;
    }
    // The representation's own property of the same name: the exposed VolumeRepresentation
    // property, input of the ShareProperties link. Falls back to the group's property when the
    // representation has no other property of that name.
    vtkSMProperty* target = smproxy->GetProperty(copy->GetXMLName());
    if (!target)
    {
      target = copy;
    }
    if (target->GetIsInternal() ||
      (target->GetPanelVisibility() && strcmp(target->GetPanelVisibility(), "never") == 0))
    {
      continue;
    }
    pqPropertyWidget* child = pqProxyWidget::createWidgetForProperty(target, smproxy, this);
    if (!child)
    {
      continue; // no standard widget (ScalarOpacityFunction): none in the panel either
    }
    const char* exposedName = smproxy->GetPropertyName(copy);
    child->setObjectName(QString(exposedName ? exposedName : copy->GetXMLName()).remove(' '));

    const int row = layout->rowCount();
    if (child->showLabel())
    {
      const char* xmlLabel = target->GetXMLLabel() ? target->GetXMLLabel() : target->GetXMLName();
      auto label = new QLabel(
        QString("<p>%1</p>").arg(QCoreApplication::translate("ServerManagerXML", xmlLabel)), this);
      label->setObjectName(child->objectName() + "Label");
      label->setWordWrap(true);
      label->setAlignment(Qt::AlignLeft | Qt::AlignTop);
      label->setToolTip(pqPropertyWidget::getTooltip(target));
      layout->addWidget(label, row, 0, Qt::AlignVCenter | Qt::AlignLeft);
      layout->addWidget(child, row, 1);
    }
    else
    {
      layout->addWidget(child, row, 0, 1, -1);
    }

    this->connect(child, SIGNAL(changeAvailable()), SIGNAL(changeAvailable()));
    this->connect(child, SIGNAL(changeFinished()), SIGNAL(changeFinished()));
    this->connect(child, SIGNAL(restartRequired()), SIGNAL(restartRequired()));
    this->Children.append(child);
  }
}

//-----------------------------------------------------------------------------
pqPsiVolumeOpacityWidget::~pqPsiVolumeOpacityWidget() = default;

//-----------------------------------------------------------------------------
void pqPsiVolumeOpacityWidget::apply()
{
  for (const auto& child : this->Children)
  {
    if (child)
    {
      child->apply();
    }
  }
  this->Superclass::apply();
}

//-----------------------------------------------------------------------------
void pqPsiVolumeOpacityWidget::reset()
{
  for (const auto& child : this->Children)
  {
    if (child)
    {
      child->reset();
    }
  }
  this->Superclass::reset();
}

//-----------------------------------------------------------------------------
void pqPsiVolumeOpacityWidget::select()
{
  for (const auto& child : this->Children)
  {
    if (child)
    {
      child->select();
    }
  }
  this->Superclass::select();
}

//-----------------------------------------------------------------------------
void pqPsiVolumeOpacityWidget::deselect()
{
  for (const auto& child : this->Children)
  {
    if (child)
    {
      child->deselect();
    }
  }
  this->Superclass::deselect();
}

//-----------------------------------------------------------------------------
void pqPsiVolumeOpacityWidget::updateWidget(bool showing_advanced_properties)
{
  for (const auto& child : this->Children)
  {
    if (child)
    {
      child->updateWidget(showing_advanced_properties);
    }
  }
  this->Superclass::updateWidget(showing_advanced_properties);
}

//-----------------------------------------------------------------------------
void pqPsiVolumeOpacityWidget::setView(pqView* aview)
{
  for (const auto& child : this->Children)
  {
    if (child)
    {
      child->setView(aview);
    }
  }
  this->Superclass::setView(aview);
}

#include "desktop/vtkShadelabInteractorStyle.h"

#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>

vtkStandardNewMacro(vtkShadelabInteractorStyle);

void vtkShadelabInteractorStyle::OnLeftButtonDown()
{
  if (!this->LineDrag)
  {
    this->Superclass::OnLeftButtonDown();
    return;
  }
  this->DrawingLine = true;
  this->Interactor->GetEventPosition(this->LineFrom);
}

void vtkShadelabInteractorStyle::OnMouseMove()
{
  if (!this->DrawingLine)
  {
    this->Superclass::OnMouseMove();
    return;
  }
  this->LineDrag(this->LineFrom, this->Interactor->GetEventPosition(), false);
}

void vtkShadelabInteractorStyle::OnLeftButtonUp()
{
  if (!this->DrawingLine)
  {
    this->Superclass::OnLeftButtonUp();
    return;
  }
  this->DrawingLine = false;
  const auto drag = std::move(this->LineDrag);
  this->LineDrag = nullptr;
  drag(this->LineFrom, this->Interactor->GetEventPosition(), true);
}

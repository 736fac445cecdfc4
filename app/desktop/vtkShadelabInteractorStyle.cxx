#include "desktop/vtkShadelabInteractorStyle.h"

#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>

vtkStandardNewMacro(vtkShadelabInteractorStyle);

void vtkShadelabInteractorStyle::OnChar()
{
  vtkRenderWindowInteractor* interactor = this->GetInteractor();
  const char code = interactor->GetKeyCode();
  const char* name = interactor->GetKeySym();
  if (!this->KeyHandler)
  {
    return;
  }
  if (code == 27)
  {
    this->KeyHandler("Escape");
  }
  else if (code > 32 && code < 127)
  {
    this->KeyHandler(std::string(1, code));
  }
  else if (name)
  {
    this->KeyHandler(name);
  }
}

#include "desktop/vtkShadelabInteractorStyle.h"

#include <vtkObjectFactory.h>

vtkStandardNewMacro(vtkShadelabInteractorStyle);

// The settings whose value is more than one kind's: the material (a name, or
// an object of coefficients), the lights (an array of objects) and the
// background (a colour, or transparent). Each is a whole Setting, made by
// hand, that the table lists as it lists the plain ones.
#ifndef shadelab_special_settings_h
#define shadelab_special_settings_h

#include "settings/setting.h"

namespace shadelab
{
namespace settings
{
/** --material and the scene files' "material" (whose object holds --ka, --kd, --ks, --ns). */
Setting MaterialSetting();

/** The repeatable --light and the scene files' "lights". */
Setting LightsSetting();

/** --background: a colour, or transparent. */
Setting BackgroundSetting();
}
}

#endif

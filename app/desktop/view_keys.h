// The inspector's keys: one table of {keys, help, action} from which the
// window's key handling (desktop/inspector_keys.cxx), its help overlay and
// the key list of `shadelab view --help` all come.
//
// Plain data, no VTK: shadelab (the OSMesa executable) prints the list in
// its --help and must not link the window's code. So a row names its action
// by an enumerator, not a function; the inspector binds the enumerators in
// one switch, without a default, which -Werror=switch (app/CMakeLists.txt)
// fails to compile if one has no case. The static_asserts below hold the
// table to one row per action and each key to one row, so no action goes
// without keys and no key is ambiguous.
#ifndef shadelab_view_keys_h
#define shadelab_view_keys_h

#include <cstddef>
#include <string_view>

namespace shadelab
{
// In the table's order.
enum class ViewAction
{
  Shading,     // the key's place in its row is the rule (0 none ... 3 phong)
  Reflection,  // Blinn-Phong / Phong
  Material,    // the first key the next, the second the previous
  Lights,      // the cycle of LightMode
  Shininess,   // the first key up, the second down
  Term,        // ambient, diffuse, specular by the key's place
  Weighting,   // the normals' cycle
  Glyphs,      // vertex-normal glyphs on / off
  Edges,       // on / off
  Compare,     // the comparison layout on / off
  ResetCamera, // the command line's camera
  Screenshot,  // into the current folder
  CopyCommand, // the render command of the picture: clipboard and stdout
  SaveScene,   // the scene file of the picture, into the current folder
  ProfileLine, // the next drag draws the profile's line
  Help,        // the overlay on / off
  Quit
};

struct ViewKey
{
  const char* Keys; // space-separated, as the help shows them
  const char* Help;
  ViewAction Action;
};

inline constexpr ViewKey ViewKeys[] = {
  { "0 1 2 3", "shading none, flat, gouraud, phong", ViewAction::Shading },
  { "b", "Blinn-Phong / Phong reflection", ViewAction::Reflection },
  { "m M", "next / previous material", ViewAction::Material },
  { "l", "lights: point at camera, directional, spot", ViewAction::Lights },
  { "+ -", "shininess up / down", ViewAction::Shininess },
  { "a d s", "ambient, diffuse, specular term on / off", ViewAction::Term },
  { "w", "normal weighting (computed once each)", ViewAction::Weighting },
  { "n", "normal glyphs", ViewAction::Glyphs },
  { "e", "edges", ViewAction::Edges },
  { "c", "comparison layout (as compare's options), linked cameras", ViewAction::Compare },
  { "r", "reset the camera", ViewAction::ResetCamera },
  { "p", "screenshot (its name is printed)", ViewAction::Screenshot },
  { "y", "copy the render command that makes this picture (and print it)",
    ViewAction::CopyCommand },
  { "j", "save the scene file that makes this picture (its name is printed)",
    ViewAction::SaveScene },
  { "k", "profile: drag a line; its intensity per rule in the Profile dock (Mach bands)",
    ViewAction::ProfileLine },
  { "h", "this help", ViewAction::Help },
  { "q Esc", "quit", ViewAction::Quit },
};

inline constexpr const char* ViewMouseHelp =
  "Mouse: left rotate, middle pan, right or wheel zoom.\n"
  "Ctrl+click: explain that pixel (the Probe dock; Clear probe there).";

/** A row's key number `which` (from 0), or "" past its last. */
constexpr std::string_view NthViewKey(std::string_view keys, int which)
{
  for (; which > 0 && !keys.empty(); --which)
  {
    const std::size_t space = keys.find(' ');
    keys = space == std::string_view::npos ? std::string_view() : keys.substr(space + 1);
  }
  return keys.substr(0, keys.find(' '));
}

struct ViewKeyPress
{
  const ViewKey* Row = nullptr; // null: not a key of the table
  int Which = 0;                // the key's place in its row
};

/** The row holding `key` (a name as the table spells it). */
constexpr ViewKeyPress FindViewKey(std::string_view key)
{
  for (const ViewKey& row : ViewKeys)
  {
    for (int which = 0; !NthViewKey(row.Keys, which).empty(); ++which)
    {
      if (NthViewKey(row.Keys, which) == key)
      {
        return { &row, which };
      }
    }
  }
  return {};
}

constexpr bool OneRowPerActionInOrder()
{
  int action = 0;
  for (const ViewKey& row : ViewKeys)
  {
    if (row.Action != static_cast<ViewAction>(action++))
    {
      return false;
    }
  }
  return action == static_cast<int>(ViewAction::Quit) + 1;
}
static_assert(OneRowPerActionInOrder(), "ViewKeys: one row per ViewAction, in its order");

constexpr bool EachKeyInOneRow()
{
  for (const ViewKey& row : ViewKeys)
  {
    for (int which = 0; !NthViewKey(row.Keys, which).empty(); ++which)
    {
      const ViewKeyPress found = FindViewKey(NthViewKey(row.Keys, which));
      if (found.Row != &row || found.Which != which)
      {
        return false;
      }
    }
  }
  return true;
}
static_assert(EachKeyInOneRow(), "ViewKeys: a key in two rows (or twice in one)");
}

#endif

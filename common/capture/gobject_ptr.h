// Ownership of GLib objects and errors from C++ (for the .cpp files of
// capture/ that call Aravis).
#pragma once

#include <memory>
#include <string>

#include <glib-object.h>

namespace ws {

struct GObjectUnref {
  void operator()(gpointer object) const {
    if (object) g_object_unref(object);
  }
};

template <class T>
using GObjectPtr = std::unique_ptr<T, GObjectUnref>;

// The message of *error ("" when there is none); frees it and clears *error.
inline std::string TakeError(GError** error) {
  if (!*error) return "";
  std::string message = (*error)->message;
  g_clear_error(error);
  return message;
}

}  // namespace ws

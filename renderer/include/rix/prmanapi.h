// prmanapi.h — which RenderMan these headers stand in for.
//
// The Rix headers here follow RenderMan 24's plugin API. Plugins written for
// several RenderMan versions choose between signatures with these macros, e.g.
//
//   #if _PRMANAPI_VERSION_MAJOR_ >= 23
//       void CreateInstanceData(...) override;  // RenderMan 23 and later
//   #else
//       int CreateInstanceData(...);            // RenderMan 22
//   #endif
//
// and build scripts look for this file in $RMANTREE/include to find the
// headers and read the version from it.
#pragma once

#define _PRMANAPI_VERSION_MAJOR_ 24
#define _PRMANAPI_VERSION_MINOR_ 0
#define _PRMANAPI_VERSION_ _PRMANAPI_VERSION_MAJOR_
#define _PRMANAPI_VERSION_STR_ "24.0"

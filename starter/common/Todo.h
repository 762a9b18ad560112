// Helpers for the exercise skeletons.
//
// RIX_TODO(sCtx, "Diffuse::GenerateSample") marks a body you have not written
// yet: the first time it runs it prints
//   warning: plugin diffuse: TODO: Diffuse::GenerateSample is not implemented yet
// and the code around it returns a safe value (black, or an invalid sample),
// so the renderer shows a black surface instead of crashing, and the grader
// can tell "not attempted" from "wrong". Delete the line when you implement
// the body.
#pragma once

#include <mutex>
#include <set>
#include <string>

#include "RixShading.h"

/// Whether `what` is reported for the first time (each TODO is reported once).
inline bool FirstTodoReport(const char* what) {
    static std::mutex lock;
    static std::set<std::string> reported;
    std::lock_guard<std::mutex> guard(lock);
    return reported.insert(what).second;
}

inline void ReportTodo(RixShadingContext const* sCtx, const char* what) {
    if (!FirstTodoReport(what)) return;
    if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
        messages->Warning("TODO: %s is not implemented yet", what);
}

/// The same from factory code (Synchronize has a RixContext, not a shading context).
inline void ReportTodo(RixContext const& ctx, const char* what) {
    if (!FirstTodoReport(what)) return;
    if (auto* messages = static_cast<RixMessages*>(ctx.GetRixInterface(k_RixMessages)))
        messages->Warning("TODO: %s is not implemented yet", what);
}

#define RIX_TODO(sCtx, what) ReportTodo(sCtx, what)

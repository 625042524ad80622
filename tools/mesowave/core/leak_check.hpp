#pragma once
// Allocations that are not mesowave's to free: OpenMPI's start and end (and hypre's) leave about
// 120 kB that LeakSanitizer reports once a process. A sanitizer build (make test-sanitize) leaves
// what is allocated while an OutsideLeakCheck lives out of its report; other builds compile it away.
#if defined(__SANITIZE_ADDRESS__)
#define MESOWAVE_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESOWAVE_LSAN 1
#endif
#endif
#ifdef MESOWAVE_LSAN
#include <sanitizer/lsan_interface.h>
#endif

namespace mesowave {

struct OutsideLeakCheck {
#ifdef MESOWAVE_LSAN
  OutsideLeakCheck() { __lsan_disable(); }
  ~OutsideLeakCheck() { __lsan_enable(); }
  OutsideLeakCheck(const OutsideLeakCheck&) = delete;
  OutsideLeakCheck& operator=(const OutsideLeakCheck&) = delete;
#endif
};

}  // namespace mesowave

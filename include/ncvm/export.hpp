#pragma once
// NCVM_API marks what libncvm.so exports: the engine inside it is built with hidden
// visibility, so only the names of these headers are part of its interface.
#if defined(__GNUC__) || defined(__clang__)
#define NCVM_API __attribute__((visibility("default")))
#else
#define NCVM_API
#endif

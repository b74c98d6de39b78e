// stb_image's implementation (Debian's libstb-dev), compiled once, for PNG, BMP and TGA
// only (BMP and TGA: the textures of older OBJ exports from 3ds Max, MilkShape and
// games, which stopped the whole scene; JPEG goes to libjpeg-turbo, jpeg_texels.h);
// io/model/texture_file.cpp calls it.
//
// This file alone is built without UBSan's nonnull-attribute check when sanitizing
// (CMakeLists.txt): for a PNG whose first IDAT chunk is empty, stb's stbi__getn copies
// zero bytes into a buffer not yet allocated, memcpy(NULL, p, 0), which reads and writes
// nothing. The fuzzer found it (fuzz/corpus/texture/empty-first-idat.png); the file
// still decodes or is refused as before, and every other check stays on here.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#define STBI_MAX_DIMENSIONS 16384  // kMaxTextureSide
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

// A platform header in the style of game engines' shared effect headers: it branches on the macros a
// compiler predefines, and fxc predefined none of glslang's.
#if defined(VULKAN) || defined(GL_SPIRV) || defined(GL_core_profile)
#error a glslang predefine reached the effect
#endif

#if defined(SM6)
#define PS_PROFILE ps_6_0
#else
#define PS_PROFILE ps_3_0
#endif

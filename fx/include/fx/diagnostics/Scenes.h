// Diagnostics: Scenes (runtime/assets/src/SceneFile.cpp, MeshImporter.cpp). One section of the table that
// fx/DiagnosticDefs.h includes, in its order; FX_DIAGNOSTIC(Id, Severity, "template"). Include
// DiagnosticDefs.h, never this file alone.
FX_DIAGNOSTIC(SceneSyntaxError, Error, "invalid JSON: {0}")
FX_DIAGNOSTIC(SceneUnknownKey, Warning, "{0}: unknown key '{1}' (ignored)")
FX_DIAGNOSTIC(MeshFileNotFound, Error, "cannot open mesh file '{0}'")
// {1}: assimp's reason.
FX_DIAGNOSTIC(MeshImportError, Error, "cannot import mesh '{0}' (assimp: {1})")
FX_DIAGNOSTIC(UnknownScene, Error, "no built-in scene named '{0}' (known: {1})")
// Invalid values in a scene file, one id per message ({0}: the key).
FX_DIAGNOSTIC(SceneObjectExpected, Error, "{0}: expected an object, found {1}")
FX_DIAGNOSTIC(SceneNumberExpected, Error, "{0}: expected a number, found {1}")
FX_DIAGNOSTIC(SceneNumberOutOfRange, Error, "{0}: value {1} out of range [{2}, {3}]")
FX_DIAGNOSTIC(SceneIntegerExpected, Error, "{0}: expected an integer in [{1}, {2}]")
FX_DIAGNOSTIC(SceneBoolExpected, Error, "{0}: expected true or false, found {1}")
FX_DIAGNOSTIC(SceneStringExpected, Error, "{0}: expected a string, found {1}")
FX_DIAGNOSTIC(SceneVectorExpected, Error, "{0}: expected an array of 3 numbers, found {1}")
FX_DIAGNOSTIC(SceneVectorOrNumberExpected, Error,
              "{0}: expected an array of 3 numbers or a number, found {1}")
FX_DIAGNOSTIC(SceneMeshFileExpected, Error, "{0}: expected a mesh file name")
FX_DIAGNOSTIC(
    SceneMeshSourceMissing, Error,
    "{0}: a mesh needs \"file\" or \"primitive\" (plane, box, sphere, torus, teapot, cylinder, cone)")
FX_DIAGNOSTIC(ScenePlaneSizeInvalid, Error, "{0}: expected a number or an array of 2 numbers [x, z]")
FX_DIAGNOSTIC(SceneUnknownPrimitive, Error,
              "{0}: unknown primitive '{1}' (plane, box, sphere, torus, teapot, cylinder, cone)")
FX_DIAGNOSTIC(SceneUnknownMesh, Error, "{0}: no mesh named '{1}' in \"meshes\"")
FX_DIAGNOSTIC(SceneMeshExpected, Error, "{0}: expected a mesh name or a mesh definition, found {1}")
FX_DIAGNOSTIC(SceneObjectWithoutMesh, Error, "{0}: an object needs a \"mesh\"")
FX_DIAGNOSTIC(SceneInstancesExpected, Error, "{0}: expected an array of transforms, found {1}")
FX_DIAGNOSTIC(SceneCameraFarNotBeyondNear, Error, "camera.far: must be greater than camera.near")
FX_DIAGNOSTIC(SceneCameraTargetAtPosition, Error, "camera.target: must differ from camera.position")
FX_DIAGNOSTIC(SceneUnknownLightType, Error, "{0}: unknown light type '{1}' (directional, spot, point)")
FX_DIAGNOSTIC(SceneLightDirectionZero, Error, "{0}: must not be zero")
FX_DIAGNOSTIC(SceneArrayExpected, Error, "{0}: expected an array, found {1}")
FX_DIAGNOSTIC(SceneWithoutObjects, Error, "objects: the scene has no objects")
FX_DIAGNOSTIC(SceneBoundsIncomplete, Error, "bounds: needs \"min\" and \"max\"")
FX_DIAGNOSTIC(SceneBoundsInverted, Error, "bounds: min must not exceed max")
FX_DIAGNOSTIC(SceneViewportHintInvalid, Error, "hints.viewport: expected [width, height], positive integers")
// nlohmann-json's own text, where a value had a type the reader did not check first.
FX_DIAGNOSTIC(SceneReadFailed, Error, "(scene): {0}")
// Invalid values in a host file ({0}: the JSON pointer), one id per message.
FX_DIAGNOSTIC(HostFrameMissing, Error,
              "{0}: frame: a host file needs a \"frame\": the steps the application draws")
FX_DIAGNOSTIC(HostFrameNotSteps, Error, "{0}: frame: expected a non-empty array of steps")
FX_DIAGNOSTIC(HostObjectExpected, Error, "{0}: expected an object, found {1}")
FX_DIAGNOSTIC(HostStringExpected, Error, "{0}: expected a string, found {1}")
FX_DIAGNOSTIC(HostTargetNamedFrame, Error, "{0}: 'frame' is the application's frame, not a target it creates")
FX_DIAGNOSTIC(
    HostTargetFormatInvalid, Error,
    "{0}: '{1}' is not a colour format (R32F, A8R8G8B8, A16B16G16R16F, G32R32F, ...; every target has "
    "a depth buffer of its own)")
FX_DIAGNOSTIC(HostTargetSizeInvalid, Error, "{0}: expected [width, height], whole numbers from 1 to 16384")
FX_DIAGNOSTIC(HostLightValueNotPositive, Error, "{0}: {1}: expected a number > 0")
FX_DIAGNOSTIC(HostLightFovTooWide, Error, "{0}: fovY: expected degrees below 180")
FX_DIAGNOSTIC(HostLightFarNotBeyondNear, Error, "{0}: far: expected more than near")
FX_DIAGNOSTIC(
    HostValueUnknown, Error,
    "{0}: '{1}' is not a matrix (World, View, Projection, WorldView, ViewProjection, "
    "WorldViewProjection, with Inverse and Transpose forms, after 'camera.' or a light's name), a "
    "light's Position, ViewPosition, Direction, ViewDirection, Color or CosHalfAngle, ObjectColor or "
    "ViewportSize")
FX_DIAGNOSTIC(HostProductNotMatrix, Error, "{0}: a product takes matrices only")
FX_DIAGNOSTIC(HostParameterValueExpected, Error,
              "{0}: expected what the parameter is (a string, an array of matrices or of numbers, a number, "
              "true or false), found {1}")
FX_DIAGNOSTIC(HostStepWithoutTechnique, Error, "{0}: a step needs a \"technique\"")
FX_DIAGNOSTIC(HostStepUnknownTarget, Error,
              "{0}: no target named '{1}' (\"targets\" creates them; \"frame\" is the application's frame)")
FX_DIAGNOSTIC(HostClearColorInvalid, Error, "{0}: expected [r, g, b, a]")
FX_DIAGNOSTIC(HostClearDepthInvalid, Error, "{0}: expected a number from 0 to 1")
FX_DIAGNOSTIC(HostStepDrawInvalid, Error, "{0}: expected \"geometry\", \"quad\" or \"nothing\", found '{1}'")
FX_DIAGNOSTIC(HostVisibilityValueInvalid, Error, "{0}: expected a number, true, false or an array of numbers")
FX_DIAGNOSTIC(
    HostUnshadowedMissing, Error,
    "{0}: expected \"unshadowed\": the targets (shadow maps) that light everything when left cleared")
FX_DIAGNOSTIC(HostUnshadowedUnknownTarget, Error, "{0}: no target named '{1}'")
FX_DIAGNOSTIC(HostTargetKindInvalid, Error,
              "{0}: expected \"2d\", \"cube\", \"array\" or \"volume\", found '{1}'")
FX_DIAGNOSTIC(HostTargetLayersInvalid, Error,
              "{0}: expected a whole number from 1 to 2048 (an array's elements or a volume's slices)")
FX_DIAGNOSTIC(HostTargetLayersWithoutLayers, Error,
              "{0}: a {1} target has no \"layers\" (only an array or a volume does; a cube has six faces)")
FX_DIAGNOSTIC(
    HostStepViewportsInvalid, Error,
    "{0}: expected 1 to 16 viewports, each [x, y, width, height] in pixels, width and height above 0")
FX_DIAGNOSTIC(HostStepDispatchInvalid, Error,
              "{0}: expected 1 to 3 group counts, each a whole number or a parameter's name")
// A host file checked against the effect it drives (fx::checkHostFile).
FX_DIAGNOSTIC(HostParameterUnknown, Error, "{0}: the effect has no parameter '{1}'")
FX_DIAGNOSTIC(HostParameterNotNumeric, Error, "{0}: '{1}' is a {2}, not a number, vector or matrix")
FX_DIAGNOSTIC(HostValueSizeMismatch, Error,
              "{0}: '{1}' is a {2} ({3} components), which this value ({4}) does not fit")
FX_DIAGNOSTIC(HostTargetTextureUnknown, Error, "{0}: the effect has no texture parameter '{1}'")
FX_DIAGNOSTIC(HostStepTechniqueUnknown, Error, "{0}: the effect has no technique '{1}'")
FX_DIAGNOSTIC(HostStepPassUnknown, Error, "{0}: technique '{1}' has no pass '{2}'")
FX_DIAGNOSTIC(HostTargetTextureKindMismatch, Error,
              "{0}: a {1} target cannot be given to '{2}', a {3} (a 2d target goes to a Texture2D or "
              "texture, a cube to a TextureCube, an array to a Texture2DArray, a volume to a Texture3D)")
// Drawing a host file's frame (runtime::HostFrame).
FX_DIAGNOSTIC(HostLightNotInScene, Error, "light: the scene has no light named '{0}'")
// {0}: the step's target, {1}: the status glCheckFramebufferStatus gave.
FX_DIAGNOSTIC(HostTargetUnbindable, Error, "target: '{0}' makes an incomplete framebuffer in OpenGL ({1})")
// A mesh file assimp read that holds nothing to draw (MeshImporter.cpp).
FX_DIAGNOSTIC(MeshWithoutTriangles, Error, "cannot import mesh '{0}': the file has no triangles")
// A mesh of a Debian package ({1}) that is not installed.
FX_DIAGNOSTIC(
    MeshFileNotInstalled, Error,
    "cannot open mesh file '{0}' (installed by the Debian package '{1}': apt-get install {1}, or run "
    "scripts/install-deps.sh)")
// The mesh import module (runtime/RuntimeModules.h) that could not be opened; {1}: its file.
FX_DIAGNOSTIC(MeshModuleMissing, Error,
              "cannot import mesh '{0}': the mesh import (assimp) module {1} is missing: looked for {2} "
              "(SHADOWFX_MODULE_DIR names the folder that holds it)")
// {2}: the dynamic loader's reason.
FX_DIAGNOSTIC(
    MeshModuleUnloadable, Error,
    "cannot import mesh '{0}': the dynamic loader refused the mesh import (assimp) module {1} ({2})")
FX_DIAGNOSTIC(
    MeshModuleEntryMissing, Error,
    "cannot import mesh '{0}': the mesh import (assimp) module {1} has no entry point '{2}': it was "
    "built from another version of shadowfx")
// A host file's value of a type the reader did not check first (as SceneReadFailed); {0}: nlohmann-json's
// message.
FX_DIAGNOSTIC(HostValueUnreadable, Error, "a value of the host file cannot be read (nlohmann-json: {0})")

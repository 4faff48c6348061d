/******************************************************************************
A "preprocess" scene effect in the style of FX Composer's library: a technique without passes whose
script clears colour and depth to the effect's own values and lets the host draw the scene
(ScriptExternal=Scene). The depth clear's plan found the host's draw and took it for a pass's draw.
******************************************************************************/

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "preprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Backdrop;";
> = 0.8;

float4 Backdrop < string UIWidget = "Color"; string UIName = "Backdrop"; > = {0.0, 0.5, 1.0, 1.0};
float BackdropDepth < string UIWidget = "none"; > = 1.0;

technique Backdrop <
    string Script = "ClearSetColor=Backdrop;"
                    "ClearSetDepth=BackdropDepth;"
                    "Clear=Color;"
                    "Clear=Depth;"
                    "ScriptExternal=Scene;";
> {
}

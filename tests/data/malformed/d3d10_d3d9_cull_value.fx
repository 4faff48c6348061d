// D3D10's CullMode names faces (NONE, FRONT, BACK), not D3D9's windings.
RasterizerState Culled { CullMode = CCW; };

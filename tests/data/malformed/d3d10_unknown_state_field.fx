// A rasterizer state with a field D3D10 does not define (D3D9's name for it).
RasterizerState Wire { FillMode = WIREFRAME; SlopeScaleDepthBias = 1.0; };

// A read-write structured buffer: FX11 binds unordered access views from the application, never a pass.
struct Particle { float3 Position; float Age; };
RWStructuredBuffer<Particle> Particles;

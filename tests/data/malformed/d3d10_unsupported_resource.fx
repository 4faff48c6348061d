// A structured buffer, which shadowfx's passes do not bind.
struct Particle { float3 Position; float Age; };
StructuredBuffer<Particle> Particles;

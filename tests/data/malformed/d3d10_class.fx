// Dynamic shader linkage: a class implementing an interface.
interface ILight { float3 Illuminate(); };
class Ambient : ILight { float3 Colour; float3 Illuminate() { return Colour; } };

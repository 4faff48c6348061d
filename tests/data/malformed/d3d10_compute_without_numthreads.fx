// A compute shader without [numthreads]: GL's compute stage needs its local size.
RWStructuredBuffer<float4> Cells < int ElementCount = 4; >;
void CS(uint3 id : SV_DispatchThreadID) { Cells[id.x] = 1; }
technique11 Computed < string Script = "Pass=Fill;"; >
{
    pass Fill < string Script = "Dispatch=4;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, CS()));
    }
}

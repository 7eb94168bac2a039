namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/ComputeShader.html
    public sealed class ComputeShader : Object
    {
        // https://docs.unity3d.com/ScriptReference/ComputeShader.FindKernel.html
        public int FindKernel(string name) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.HasKernel.html
        public bool HasKernel(string name) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.GetKernelThreadGroupSizes.html
        public void GetKernelThreadGroupSizes(int kernelIndex, out uint x, out uint y, out uint z) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.SetBuffer.html
        public void SetBuffer(int kernelIndex, int nameID, GraphicsBuffer buffer) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.SetTexture.html
        public void SetTexture(int kernelIndex, int nameID, Texture texture) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.SetInts.html
        public void SetInts(int nameID, params int[] values) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.SetConstantBuffer.html
        public void SetConstantBuffer(int nameID, GraphicsBuffer buffer, int offset, int size) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.Dispatch.html
        public void Dispatch(int kernelIndex, int threadGroupsX, int threadGroupsY, int threadGroupsZ) => throw null;

        // https://docs.unity3d.com/ScriptReference/ComputeShader.DispatchIndirect.html
        public void DispatchIndirect(int kernelIndex, GraphicsBuffer argsBuffer, uint argsOffset = 0) => throw null;
    }
}

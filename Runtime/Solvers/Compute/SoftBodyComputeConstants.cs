using System.Runtime.InteropServices;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The constants of the soft-body kernels, uploaded whole per substep as their constant buffer: the C# side of
    /// <c>Shaders/Kernels/SoftBodyComputeConstants.hlsl</c>, with the same fields in the same order at the same byte offsets.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SoftBodyComputeConstants
    {
        /// <summary>Bytes of the constant buffer: a multiple of 16, as constant buffers require.</summary>
        public const int Bytes = 16;
        /// <summary>The constant buffer's name in HLSL (its shader property).</summary>
        public const string BufferName = "SoftBodyComputeConstants";

        /// <summary>Substep h (s).</summary>
        public float SubstepSeconds;
        /// <summary>1/h² (1/s²).</summary>
        public float InverseSubstepSquared;
        /// <summary>1/h (1/s).</summary>
        public float InverseSubstep;
        /// <summary>Fills the 16-byte row.</summary>
        public float Unused;

        /// <summary>The constants of a substep of <paramref name="h"/> seconds.</summary>
        public static SoftBodyComputeConstants Of(float h) => new SoftBodyComputeConstants
        {
            SubstepSeconds = h,
            InverseSubstepSquared = 1f / (h * h),
            InverseSubstep = 1f / h,
        };
    }
}

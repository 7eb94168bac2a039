// The constants of the soft-body kernels, one constant buffer uploaded whole per substep: the HLSL side of
// Runtime/Solvers/Compute/SoftBodyComputeConstants.cs (same fields, same order, same byte offsets; a test checks it).
#ifndef SBD_SOFT_BODY_COMPUTE_CONSTANTS_INCLUDED
#define SBD_SOFT_BODY_COMPUTE_CONSTANTS_INCLUDED

cbuffer SoftBodyComputeConstants
{
    float SubstepSeconds;           // substep h (s)
    float InverseSubstepSquared;    // 1/h² (1/s²)
    float InverseSubstep;           // 1/h (1/s)
    float Unused;                   // fills the row: the size stays a multiple of 16 bytes
};

#endif

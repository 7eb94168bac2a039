// The constants of the fluid kernels, one constant buffer uploaded whole per step and per substep length: the HLSL
// side of Runtime/Solvers/Compute/FluidComputeConstants.cs (same fields, same order, same byte offsets; a test checks
// it). Laid out under HLSL constant-buffer packing: every row is 16 bytes, a float3 starts a row and a scalar closes it.
#ifndef SBD_FLUID_COMPUTE_CONSTANTS_INCLUDED
#define SBD_FLUID_COMPUTE_CONSTANTS_INCLUDED

cbuffer FluidComputeConstants
{
    float3 GridOrigin;                  // grid origin (m)
    float InverseCellSize;              // 1 / cell size (1/m)
    int3 GridDimensions;                // cells along each axis
    uint CellCount;                     // cells in all (= the dead key)
    float3 DomainMin;                   // (m)
    float WallDistance;                 // (m)
    float3 DomainMax;                   // (m)
    float WallScale;                    // position-based walls' density scale κ
    float3 Gravity;                     // (m/s²)
    float ArtificialPressureScale;      // position-based artificial pressure k·λ₁ (m²)
    float SmoothingLength;              // kernel radius H (m)
    float SmoothingLengthSquared;       // H² (m²)
    float Poly6Coefficient;
    float SpikyGradientCoefficient;
    float CohesionCoefficient;
    float CohesionOffset;
    float ViscosityLaplacianCoefficient;
    float GradientCorrection;           // gradient correction κ∇
    float ParticleMass;                 // (kg)
    float RestDensity;                  // ρ₀ (kg/m³)
    float TaitStiffness;                // Tait B (Pa)
    float MaxDensityRatio;
    float SubstepSeconds;               // substep h (s)
    float MaxSpeed;                     // (m/s)
    float ArtificialViscosity;          // 2·α·c₀·H
    float Relaxation;                   // position-based relaxation ε
    float CohesionWeight;               // (1/s²)
    float SeparationWeight;             // (1/s²)
    float ParticleSpacing;              // (m)
    float SurfaceTension;               // γ
    float ViscosityScale;               // h·ν·2m·(Laplacian coefficient)·(viscosity correction)
    float AlignmentBlend;               // 1 − e^(−rate·h)
    float StepSeconds;                  // step dt (s)
    float BulkPressureScale;            // FluidConstants.BulkPressureScale
    uint WeaklyCompressible;            // 1 for the weakly compressible solver, 0 for position-based
    uint Flocking;                      // 1 when flocking cohesion acts
    uint Akinci;                        // 1 when Akinci surface tension acts
    uint ColliderCount;                 // colliders at the start of _Shapes
    float3 DomainFriction;              // the domain faces' friction μ per axis
    float ColliderFriction;             // the colliders' friction μ
    float3 Period;                      // the domain's extent on its periodic axes (m), 0 on the others
    float IsPeriodic;                   // 1 when any axis is periodic
    float3 InversePeriod;               // 1 / the period on the periodic axes (1/m), 0 on the others
    uint DrainCount;                    // drains in _Shapes after the colliders
    float3 FaceNoSlip;                  // no-slip share of the domain faces per axis (0 on periodic axes)
    float ColliderNoSlip;               // the colliders' no-slip share
    float GradientTraceScale;           // −κ∇·m·C_spiky
    float MaxGradientRenormalization;   // largest gradient renormalization
    float ViscosityMomentScale;         // FluidConstants.ViscosityMomentScale (m⁶/kg)
    float Padding;                      // unused: fills the last 16-byte row
};

#endif

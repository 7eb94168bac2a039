using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Linear tetrahedral finite elements as the solve stage of <see cref="ParticleBodyStep"/>: each substep adds the
    /// elements' internal forces to the velocities with the chosen integrator (<see cref="FemIntegrator"/>). Holds
    /// pointers to the model's and the state's arrays (the caller keeps them pinned for the step:
    /// <see cref="FemSolver.Step"/> does) and the counters of the step.
    /// </summary>
    public unsafe struct FemSolveStage : IParticleSolveStage
    {
        readonly float3* m_Rest;
        readonly float* m_Masses;
        readonly float* m_InverseMasses;
        readonly TetElement* m_Elements;
        readonly int* m_IncidenceOffsets;
        readonly int* m_IncidenceSlots;
        readonly int* m_ColorOffsets;
        readonly int* m_ColorElements;
        readonly float* m_StiffnessDiagonal;
        readonly quaternion* m_Rotations;
        readonly float3* m_Work;
        readonly float3* m_Slots;
        readonly float3* m_Multipliers;
        readonly float3* m_Tangents;
        readonly float3* m_WarmStart;
        readonly int* m_ElementNodes;
        readonly float3* m_PointGradients;
        readonly float* m_PointVolumes;
        readonly int* m_FactorNodes;
        readonly int* m_FactorRowStarts;
        readonly float* m_FactorValues;
        readonly int m_FactorNodeCount, m_FactorValueCount;
        readonly int m_ParticleCount, m_ElementCount, m_ColorCount, m_ElementNodeCount, m_PointCount, m_SlotCount, m_WarmStartCount;
        readonly float3 m_RestCenter;
        readonly float m_Mu, m_Lambda, m_DampingRatio, m_DefaultDampingFrequency;
        readonly FemParameters m_Parameters;
        readonly FemIntegrator m_Integrator;
        readonly float m_Beta;

        /// <summary>Most CG iterations of any implicit substep of the step.</summary>
        public int MaxCgIterations;
        /// <summary>CG iterations of the step's implicit substeps, summed.</summary>
        public int TotalCgIterations;
        /// <summary>Every implicit substep of the step converged.</summary>
        public bool CgConverged;
        /// <summary>The largest relative residual ‖r‖/‖b‖ any implicit substep's CG solve ended at.</summary>
        public float MaxCgResidual;
        /// <summary>Elements with det F ≤ 0 at the start of the last substep (explicit and implicit).</summary>
        public int InvertedElements;

        /// <summary>The stage over pinned arrays; see <see cref="FemSolver.Step"/> for how they are obtained.</summary>
        public FemSolveStage(float3* rest, float* masses, float* inverseMasses, TetElement* elements, int* incidenceOffsets,
            int* incidenceSlots, int* colorOffsets, int* colorElements, float* stiffnessDiagonal, quaternion* rotations,
            float3* work, float3* slots, float3* multipliers, float3* tangents, float3* warmStart, int* elementNodes,
            float3* pointGradients, float* pointVolumes, int* factorNodes, int* factorRowStarts, float* factorValues, in FemModel model,
            in FemState state, in FemParameters sanitizedParameters, FemIntegrator integrator, float beta)
        {
            m_FactorNodes = factorNodes;
            m_FactorRowStarts = factorRowStarts;
            m_FactorValues = factorValues;
            m_FactorNodeCount = model.FactorNodes.Length;
            m_FactorValueCount = model.FactorValues.Length;
            m_WarmStart = warmStart;
            m_WarmStartCount = state.WarmStart.Length == model.ParticleCount ? model.ParticleCount : 0;
            m_ElementNodes = elementNodes;
            m_PointGradients = pointGradients;
            m_PointVolumes = pointVolumes;
            m_ElementNodeCount = model.ElementNodes.Length;
            m_PointCount = model.PointCount;
            m_SlotCount = model.SlotCount;
            m_Rest = rest;
            m_Masses = masses;
            m_InverseMasses = inverseMasses;
            m_Elements = elements;
            m_IncidenceOffsets = incidenceOffsets;
            m_IncidenceSlots = incidenceSlots;
            m_ColorOffsets = colorOffsets;
            m_ColorElements = colorElements;
            m_StiffnessDiagonal = stiffnessDiagonal;
            m_Rotations = rotations;
            m_Work = work;
            m_Slots = slots;
            m_Multipliers = multipliers;
            m_Tangents = tangents;
            m_ParticleCount = model.ParticleCount;
            m_ElementCount = model.ElementCount;
            m_ColorCount = model.ColorCount;
            m_RestCenter = model.RestCenter;
            m_Mu = model.Mu;
            m_Lambda = model.Lambda;
            m_DampingRatio = model.DampingRatio;
            m_DefaultDampingFrequency = model.DefaultDampingFrequency;
            m_Parameters = sanitizedParameters;
            m_Integrator = integrator;
            m_Beta = beta;
            MaxCgIterations = 0;
            TotalCgIterations = 0;
            CgConverged = true;
            MaxCgResidual = 0f;
            InvertedElements = 0;
        }

        FemModel Model => new FemModel(new ReadOnlySpan<float3>(m_Rest, m_ParticleCount), new ReadOnlySpan<float>(m_Masses, m_ParticleCount),
            new ReadOnlySpan<float>(m_InverseMasses, m_ParticleCount), new ReadOnlySpan<TetElement>(m_Elements, m_ElementCount),
            new ReadOnlySpan<int>(m_IncidenceOffsets, m_ParticleCount + 1), new ReadOnlySpan<int>(m_IncidenceSlots, m_SlotCount),
            new ReadOnlySpan<int>(m_ColorOffsets, m_ColorCount + 1), new ReadOnlySpan<int>(m_ColorElements, m_ElementCount),
            new ReadOnlySpan<float>(m_StiffnessDiagonal, m_ParticleCount), m_RestCenter, m_Mu, m_Lambda, m_DampingRatio,
            m_DefaultDampingFrequency, new ReadOnlySpan<int>(m_ElementNodes, m_ElementNodeCount),
            new ReadOnlySpan<float3>(m_PointGradients, m_ElementNodeCount == 0 ? 0 : QuadraticTet.NodeCount * m_PointCount),
            new ReadOnlySpan<float>(m_PointVolumes, m_ElementNodeCount == 0 ? 0 : m_PointCount),
            new ReadOnlySpan<int>(m_FactorNodes, m_FactorNodeCount), new ReadOnlySpan<int>(m_FactorRowStarts, m_FactorValueCount == 0 ? 0 : 3 * m_FactorNodeCount + 1),
            new ReadOnlySpan<float>(m_FactorValues, m_FactorValueCount));

        Span<quaternion> Rotations => new Span<quaternion>(m_Rotations, m_PointCount);

        Span<float3> WarmStart => new Span<float3>(m_WarmStart, m_WarmStartCount);

        /// <inheritdoc/>
        public void Solve(in ParticleBody body, in ParticleStepConstants constants, in RigidFrame frame, bool lastSubstep)
        {
            FemModel model = Model;
            float h = constants.H;
            var x = body.Positions;
            var v = body.Velocities;
            var slots = new Span<float3>(m_Slots, m_SlotCount);
            ReadOnlySpan<float> w = model.InverseMasses;
            // Pinned nodes arrive at rest: the shared step zeroes their velocity before the solve (FemSolver.Body passes
            // the inverse masses), so no spurious velocity reaches the damping or the implicit system's K v.
            switch (m_Integrator)
            {
                case FemIntegrator.ImplicitEuler:
                {
                    // Neo-Hookean only: the element tangents (the co-rotational model keeps its stiffness in the rotations).
                    var tangents = m_Parameters.Model == FemMaterialModel.NeoHookean
                        ? new Span<float3>(m_Tangents, NeoHookeanTangent.Float3Count * m_PointCount)
                        : default;
                    int iterations = FemImplicitEuler.Solve(model, m_Parameters.Model, x, v, Rotations, tangents, m_Parameters.RotationIterations,
                        slots, body.Scratch, new Span<float3>(m_Work, FemState.WorkVectors * m_ParticleCount), WarmStart,
                        constants.Contact.KeepTouching ? body.ContactNormals : default, h, m_Beta,
                        m_Parameters.NewtonIterations, m_Parameters.CgIterations, m_Parameters.CgTolerance, out bool converged,
                        out float residual, out InvertedElements);
                    MaxCgIterations = math.max(MaxCgIterations, iterations);
                    TotalCgIterations += iterations;
                    CgConverged &= converged;
                    MaxCgResidual = math.max(MaxCgResidual, residual);
                    break;
                }
                case FemIntegrator.Xpbd:
                {
                    // Predict p = x + d with d = h v, project colour by colour, v = d / h.
                    Span<float3> d = body.Scratch;
                    for (int i = 0; i < x.Length; i++)
                        d[i] = w[i] > 0f ? h * v[i] : float3.zero;
                    var multipliers = new Span<float3>(m_Multipliers, m_ElementCount);
                    multipliers.Clear();
                    for (int it = 0; it < m_Parameters.Iterations; it++)
                        for (int c = 0; c < m_ColorCount; c++)
                            FemXpbd.Project(model, model.ColorElements, x, d, multipliers, h, m_Beta, model.ColorOffsets[c], model.ColorOffsets[c + 1]);
                    float invH = 1f / h;
                    for (int i = 0; i < x.Length; i++)
                        v[i] = d[i] * invH;
                    break;
                }
                default:
                {
                    // Symplectic Euler: v += h M⁻¹ (f_elastic + f_damping) at x.
                    InvertedElements = FemForces.Elastic(model, m_Parameters.Model, x, v, m_Beta, Rotations, m_Parameters.RotationIterations,
                        slots, 0, m_ElementCount);
                    Span<float3> f = body.Scratch;
                    FemForces.Gather(model, slots, f, 0, m_ParticleCount);
                    for (int i = 0; i < x.Length; i++)
                        v[i] += h * w[i] * f[i];
                    break;
                }
            }
        }

        /// <summary>The body is back at its rest shape rotated by <paramref name="rotation"/>: every point's rotation restarts there, the warm start at 0.</summary>
        public void OnReset(quaternion rotation)
        {
            Rotations.Fill(rotation);
            WarmStart.Clear();
        }
    }
}

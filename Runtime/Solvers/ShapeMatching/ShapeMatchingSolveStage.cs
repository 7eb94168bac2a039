using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Shape matching as the solve stage of <see cref="ParticleBodyStep"/> (Müller et al. 2005): each substep, the
    /// clusters are matched to the positions xᵢ (<see cref="ClusterGoals"/>) and every particle is pulled toward its
    /// goal, Δᵢ = α (gᵢ − xᵢ), vᵢ += Δᵢ / h (eq. 3 as a velocity change). Holds pointers to the model's and the state's
    /// arrays (the caller keeps them pinned for the step: <see cref="ShapeMatchingSolver.Step"/> does) and the counters
    /// of the step.
    /// </summary>
    public unsafe struct ShapeMatchingSolveStage : IParticleSolveStage
    {
        readonly float3* m_Rest;
        readonly float* m_Masses;
        readonly float* m_InverseClusterCounts;
        readonly int* m_ClusterOffsets;
        readonly int* m_ClusterParticles;
        readonly float* m_ClusterWeights;
        readonly ClusterRestData* m_ClusterRest;
        readonly float3x3* m_ModelQuadratic;
        readonly ClusterState* m_Clusters;
        readonly float3x3* m_StateQuadratic;
        readonly int m_ParticleCount, m_ClusterCount, m_MemberCount, m_ModelQuadraticLength, m_StateQuadraticLength;
        readonly ClusterRestData m_BodyRest;
        readonly ShapeMatchingParameters m_Parameters;

        /// <summary>Clusters that used a fallback in the last substep (rigid for linear, linear for quadratic).</summary>
        public int Fallbacks;
        /// <summary>Most rotation-extraction iterations any cluster needed in the step.</summary>
        public int MaxRotationIterations;
        /// <summary>Plastic updates in the step.</summary>
        public int PlasticUpdates;
        /// <summary>Plasticity was asked for in quadratic mode without per-instance quadratic inverses.</summary>
        public bool PlasticityUnavailable;

        /// <summary>The stage over pinned arrays; see <see cref="ShapeMatchingSolver.Step"/> for how they are obtained.</summary>
        public ShapeMatchingSolveStage(float3* rest, float* masses, float* inverseClusterCounts, int* clusterOffsets,
            int* clusterParticles, float* clusterWeights, ClusterRestData* clusterRest, float3x3* modelQuadratic,
            ClusterState* clusters, float3x3* stateQuadratic, in ShapeMatchingModel model, in ShapeMatchingState state,
            in ShapeMatchingParameters sanitizedParameters)
        {
            m_Rest = rest;
            m_Masses = masses;
            m_InverseClusterCounts = inverseClusterCounts;
            m_ClusterOffsets = clusterOffsets;
            m_ClusterParticles = clusterParticles;
            m_ClusterWeights = clusterWeights;
            m_ClusterRest = clusterRest;
            m_ModelQuadratic = modelQuadratic;
            m_Clusters = clusters;
            m_StateQuadratic = stateQuadratic;
            m_ParticleCount = model.ParticleCount;
            m_ClusterCount = model.ClusterCount;
            m_MemberCount = model.ClusterParticles.Length;
            m_ModelQuadraticLength = model.QuadraticInverse.Length;
            m_StateQuadraticLength = state.QuadraticInverse.Length;
            m_BodyRest = model.BodyRest;
            m_Parameters = sanitizedParameters;
            Fallbacks = 0;
            MaxRotationIterations = 0;
            PlasticUpdates = 0;
            PlasticityUnavailable = false;
        }

        ShapeMatchingModel Model => new ShapeMatchingModel(
            new ReadOnlySpan<float3>(m_Rest, m_ParticleCount), new ReadOnlySpan<float>(m_Masses, m_ParticleCount),
            new ReadOnlySpan<float>(m_InverseClusterCounts, m_ParticleCount),
            new ReadOnlySpan<int>(m_ClusterOffsets, m_ClusterCount + 1), new ReadOnlySpan<int>(m_ClusterParticles, m_MemberCount),
            new ReadOnlySpan<float>(m_ClusterWeights, m_MemberCount), new ReadOnlySpan<ClusterRestData>(m_ClusterRest, m_ClusterCount),
            new ReadOnlySpan<float3x3>(m_ModelQuadratic, m_ModelQuadraticLength), m_BodyRest);

        Span<ClusterState> Clusters => new Span<ClusterState>(m_Clusters, m_ClusterCount);

        Span<float3x3> StateQuadratic => new Span<float3x3>(m_StateQuadratic, m_StateQuadraticLength);

        /// <inheritdoc/>
        public void Solve(in ParticleBody body, in ParticleStepConstants constants, in RigidFrame frame, bool lastSubstep)
        {
            ShapeMatchingModel model = Model;
            var state = new ShapeMatchingState(body.Positions, body.Velocities, Clusters, StateQuadratic, body.Predicted,
                body.Scratch, body.ContactNormals);
            // Goals of the positions xᵢ; plastic flow once per step, on its last substep.
            ClusterGoals.Counters counters = ClusterGoals.Compute(model, m_Parameters, state, body.Positions,
                lastSubstep ? constants.Dt : 0f);
            PullTowardGoals(model, body, frame, constants.Pull, constants.H);
            MaxRotationIterations = math.max(MaxRotationIterations, counters.MaxIterations);
            PlasticUpdates += counters.PlasticUpdates;
            Fallbacks = counters.Fallbacks;
            PlasticityUnavailable |= counters.PlasticityUnavailable;
        }

        /// <summary>
        /// Each cluster keeps its plastic rest shape (Sₚ, A_qq⁻¹, quadratic inverse) when it is finite: the guard undoes
        /// a broken state, not the body's history. Rotations restart at the body's.
        /// </summary>
        public void OnReset(quaternion rotation)
        {
            ShapeMatchingModel model = Model;
            Span<ClusterState> clusters = Clusters;
            Span<float3x3> quadratic = StateQuadratic;
            for (int c = 0; c < clusters.Length; c++)
            {
                ref ClusterState cluster = ref clusters[c];
                bool plasticFinite = Finite.All(cluster.PlasticDeformation) && Finite.All(cluster.Rest.AqqInverse)
                                     && math.determinant(cluster.PlasticDeformation) > 0f;
                if (plasticFinite)
                    cluster.Rotation = rotation;
                else
                    cluster = new ClusterState { Rotation = rotation, PlasticDeformation = float3x3.identity, Rest = model.ClusterRest[c] };
            }
            if (!Finite.All(quadratic) && quadratic.Length == model.QuadraticInverse.Length)
                model.QuadraticInverse.CopyTo(quadratic);
        }

        /// <summary>
        /// Eq. 3 as a velocity change: Δᵢ = α (gᵢ − xᵢ), vᵢ += Δᵢ / h, so the position the substep then predicts,
        /// xᵢ + h vᵢ, has moved by Δᵢ toward the goal. Shape matching is an internal force, so the pull must change
        /// neither momentum nor angular momentum; two projections make that hold to round-off:
        /// <list type="bullet">
        /// <item>Σ mᵢ Δᵢ = 0 in exact arithmetic, but the float32 rest offsets do not sum to exactly zero
        /// and that residual is the same every substep: the mass-weighted mean of Δ is removed.</item>
        /// <item>The pull is torque-free about x_cm in exact arithmetic (Σ mᵢ gᵢ pᵢᵀ is symmetric for the
        /// polar rotation and for A = A_pq A_qq⁻¹), but not to the rotation's stopping tolerance and float32
        /// round-off. The rigid rotation δθ × (xᵢ − x_cm) with I δθ = Σ mᵢ (xᵢ − x_cm) × Δᵢ is removed.</item>
        /// </list>
        /// The goals are in <see cref="ParticleBody.Scratch"/> on entry (<see cref="ClusterGoals.Compute"/>).
        /// </summary>
        static void PullTowardGoals(in ShapeMatchingModel model, in ParticleBody body, in RigidFrame frame, float alpha, float h)
        {
            if (body.HasPins)
            {
                PullTowardGoalsPinned(model, body, alpha, h);
                return;
            }
            var x = body.Positions;
            var v = body.Velocities;
            var delta = body.Scratch;
            float3 drift = float3.zero;
            float mass = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                if (!(model.InverseClusterCounts[i] > 0f))
                    continue;
                delta[i] -= x[i];
                drift += model.Masses[i] * delta[i];
                mass += model.Masses[i];
            }
            if (!(mass > 0f) || !(alpha > 0f))
                return;
            drift /= mass;
            float3 xcm = frame.Center;
            float3 torque = float3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                delta[i] = model.InverseClusterCounts[i] > 0f ? alpha * (delta[i] - drift) : float3.zero;
                torque += model.Masses[i] * math.cross(x[i] - xcm, delta[i]);
            }
            float3 spin = math.mul(frame.InverseInertia, torque);
            if (!math.all(math.isfinite(spin)))
                spin = float3.zero;
            float invH = 1f / h;
            for (int i = 0; i < x.Length; i++)
                v[i] += (delta[i] - math.cross(spin, x[i] - xcm)) * invH;
        }

        /// <summary>
        /// Eq. 3 as a velocity change for a body with pinned particles: the pins hold the body, so its momentum and
        /// angular momentum are not conserved and the two projections of <see cref="PullTowardGoals"/> do not apply;
        /// each free particle moves Δᵢ = α (gᵢ − xᵢ) toward its goal (vᵢ += Δᵢ / h), a pinned one (wᵢ = 0) not at all.
        /// </summary>
        static void PullTowardGoalsPinned(in ShapeMatchingModel model, in ParticleBody body, float alpha, float h)
        {
            if (!(alpha > 0f))
                return;
            var x = body.Positions;
            var v = body.Velocities;
            var goals = body.Scratch;
            float scale = alpha / h;
            for (int i = 0; i < x.Length; i++)
                if (model.InverseClusterCounts[i] > 0f && body.InverseMasses[i] > 0f)
                    v[i] += (goals[i] - x[i]) * scale;
        }
    }
}

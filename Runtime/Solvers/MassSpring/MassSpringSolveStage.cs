using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A mass-spring network as the solve stage of <see cref="ParticleBodyStep"/>. Each substep (h) it turns the
    /// springs' forces into velocities with the chosen <see cref="MassSpringIntegrator"/>; the shared step then moves
    /// the particles, x* = x + h v, collides and updates. Holds pointers to the model's arrays and to its own scratch
    /// (the caller keeps them pinned for the step: <see cref="MassSpringSolver.Step"/> does); never uses
    /// <see cref="ParticleBody.Scratch"/>, so it can share a body with another stage (<see cref="CompositeSolveStage{TFirst,TSecond}"/>).
    /// Per-spring passes run in batches of <see cref="Batch"/> springs (the unit a job would take); the result has the
    /// same bits for any batch size.
    /// </summary>
    public unsafe struct MassSpringSolveStage : IParticleSolveStage
    {
        readonly float3* m_Rest;
        readonly float* m_Masses;
        readonly float* m_InverseMasses;
        readonly Spring* m_Springs;
        readonly int* m_IncidenceOffsets;
        readonly int* m_IncidenceSlots;
        readonly int* m_ColorOffsets;
        readonly int* m_ColorSprings;
        readonly float3* m_Scratch;
        readonly float3* m_SpringScratch;
        readonly int m_ParticleCount, m_SpringCount, m_ColorCount;
        readonly MassSpringParameters m_Parameters;
        int m_Substep;

        /// <summary>Springs per batch of the per-spring and per-particle passes; 0 = one batch.</summary>
        public int Batch;
        /// <summary>Implicit Euler: most CG iterations any substep of the step took.</summary>
        public int MaxCgIterations;
        /// <summary>Implicit Euler: substeps whose CG stopped at the iteration cap above the tolerance.</summary>
        public int CgUnconverged;

        /// <summary>
        /// The stage over pinned arrays. <paramref name="scratch"/> holds <see cref="MassSpringState.ScratchPerParticle"/>
        /// float3 per particle, <paramref name="springScratch"/> <see cref="MassSpringState.ScratchPerSpring"/> per spring.
        /// </summary>

        public MassSpringSolveStage(float3* rest, float* masses, float* inverseMasses, Spring* springs, int* incidenceOffsets,
            int* incidenceSlots, int* colorOffsets, int* colorSprings, float3* scratch, float3* springScratch, int particleCount,
            int springCount, int colorCount, in MassSpringParameters sanitizedParameters)
        {
            m_Rest = rest;
            m_Masses = masses;
            m_InverseMasses = inverseMasses;
            m_Springs = springs;
            m_IncidenceOffsets = incidenceOffsets;
            m_IncidenceSlots = incidenceSlots;
            m_ColorOffsets = colorOffsets;
            m_ColorSprings = colorSprings;
            m_Scratch = scratch;
            m_SpringScratch = springScratch;
            m_ParticleCount = particleCount;
            m_SpringCount = springCount;
            m_ColorCount = colorCount;
            m_Parameters = sanitizedParameters;
            m_Substep = 0;
            Batch = 0;
            MaxCgIterations = 0;
            CgUnconverged = 0;
        }

        ReadOnlySpan<float3> Rest => new ReadOnlySpan<float3>(m_Rest, m_ParticleCount);
        ReadOnlySpan<float> Masses => new ReadOnlySpan<float>(m_Masses, m_ParticleCount);
        ReadOnlySpan<float> InverseMasses => new ReadOnlySpan<float>(m_InverseMasses, m_ParticleCount);
        ReadOnlySpan<Spring> Springs => new ReadOnlySpan<Spring>(m_Springs, m_SpringCount);
        ReadOnlySpan<int> Offsets => new ReadOnlySpan<int>(m_IncidenceOffsets, m_ParticleCount + 1);
        ReadOnlySpan<int> Slots => new ReadOnlySpan<int>(m_IncidenceSlots, 2 * m_SpringCount);
        /// <summary>Particle scratch block k (see <see cref="MassSpringState.ScratchPerParticle"/>); 0 and 1 belong to the shared step.</summary>
        Span<float3> Block(int k) => new Span<float3>(m_Scratch + k * m_ParticleCount, m_ParticleCount);
        Span<float3> SlotValues => new Span<float3>(m_SpringScratch, 2 * m_SpringCount);
        Span<float3> Frames => new Span<float3>(m_SpringScratch + 2 * m_SpringCount, 2 * m_SpringCount);

        const int ForceBlock = 2, PreviousBlock = 3, DeltaBlock = 4, ResidualBlock = 5, PreconditionedBlock = 6,
            DirectionBlock = 7, ProductBlock = 8, DiagonalBlock = 9;

        /// <inheritdoc/>
        public void Solve(in ParticleBody body, in ParticleStepConstants constants, in RigidFrame frame, bool lastSubstep)
        {
            float h = constants.H;
            switch (m_Parameters.Integrator)
            {
                case MassSpringIntegrator.Verlet:
                    Verlet(body.Positions, body.Velocities, h, constants.Gravity);
                    break;
                case MassSpringIntegrator.ImplicitEuler:
                    ImplicitEuler(body.Positions, body.Velocities, h, frame.Mass);
                    break;
                case MassSpringIntegrator.Xpbd:
                    Xpbd(body.Positions, body.Velocities, h);
                    break;
                default:
                    SymplecticEuler(body.Positions, body.Velocities, h);
                    break;
            }
            m_Substep = lastSubstep ? 0 : m_Substep + 1;
        }

        /// <summary>Nothing of the stage outlives a step except Verlet's substep count, which restarts.</summary>
        public void OnReset(quaternion rotation) => m_Substep = 0;

        /// <summary>Fᵢ = Σ of the spring and dashpot forces on particle i at (x, v), by slots and a fixed-order gather.</summary>
        void GatherForces(ReadOnlySpan<float3> x, ReadOnlySpan<float3> v, Span<float3> force)
        {
            int batch = Batch > 0 ? Batch : math.max(1, m_SpringCount);
            for (int s = 0; s < m_SpringCount; s += batch)
                SpringForces.Compute(Springs, Rest, x, v, s, math.min(s + batch, m_SpringCount), SlotValues);
            GatherSlots(force);
        }

        /// <summary>result = Σ per-slot values, per particle, in batches of particles.</summary>
        void GatherSlots(Span<float3> result)
        {
            result.Clear();
            int batch = Batch > 0 ? Batch : math.max(1, m_ParticleCount);
            for (int s = 0; s < m_ParticleCount; s += batch)
                ElementIncidence.Gather(Offsets, Slots, SlotValues, s, math.min(s + batch, m_ParticleCount), result);
        }

        /// <summary>Symplectic Euler: v += h M⁻¹ f(x, v) (the shared step then sets x += h v).</summary>
        void SymplecticEuler(Span<float3> x, Span<float3> v, float h)
        {
            Span<float3> force = Block(ForceBlock);
            GatherForces(x, v, force);
            ReadOnlySpan<float> w = InverseMasses;
            for (int i = 0; i < m_ParticleCount; i++)
                v[i] += h * w[i] * force[i];
        }

        /// <summary>
        /// Störmer–Verlet, x_{n+1} = 2xₙ − x_{n−1} + h² (M⁻¹ f(xₙ, uₙ) + g), with the dashpots' velocity the backward
        /// difference uₙ = (xₙ − x_{n−1})/h. Seeded at the first substep of each step from the velocities (which the
        /// shared step wrote or a user set): x_{−1} = x − h (v − h g), v − h g being the velocity before this substep's
        /// gravity. Writes v = (x_{n+1} − xₙ)/h so the shared step's x + h v is x_{n+1}; keeps xₙ as the next x_{n−1}.
        /// In exact arithmetic the positions are those of symplectic Euler.
        /// </summary>
        void Verlet(Span<float3> x, Span<float3> v, float h, float3 g)
        {
            Span<float3> previous = Block(PreviousBlock);
            Span<float3> u = Block(ProductBlock);
            Span<float3> force = Block(ForceBlock);
            float invH = 1f / h;
            if (m_Substep == 0)
                for (int i = 0; i < m_ParticleCount; i++)
                    previous[i] = x[i] - h * (v[i] - h * g);
            for (int i = 0; i < m_ParticleCount; i++)
                u[i] = (x[i] - previous[i]) * invH;
            GatherForces(x, u, force);
            ReadOnlySpan<float> w = InverseMasses;
            float h2 = h * h;
            for (int i = 0; i < m_ParticleCount; i++)
            {
                float3 next = w[i] == 0f ? x[i] : 2f * x[i] - previous[i] + h2 * (w[i] * force[i] + g);
                v[i] = (next - x[i]) * invH;
                previous[i] = x[i];
            }
        }

        /// <summary>
        /// Linearised backward Euler (Baraff &amp; Witkin 1998, eq. 15–18): (M − h ∂f/∂v − h² ∂f/∂x) Δv = h (f + h ∂f/∂x v),
        /// v += Δv, solved by conjugate gradients with a Jacobi preconditioner, matrix-free (per-spring blocks, see
        /// <see cref="SpringForces.ImplicitFrames"/>). Pinned particles are held by the filter of Baraff &amp; Witkin §5.3:
        /// their rows of b, r and the search directions are zero, so Δv = 0 there. Without pins the internal forces cannot
        /// change the momentum; the CG residual (≤ tolerance) can, so its mass-weighted mean is removed from Δv.
        /// </summary>
        void ImplicitEuler(Span<float3> x, Span<float3> v, float h, float totalMass)
        {
            ReadOnlySpan<float> m = Masses;
            ReadOnlySpan<float> w = InverseMasses;
            Span<float3> dv = Block(DeltaBlock), r = Block(ResidualBlock), z = Block(PreconditionedBlock),
                p = Block(DirectionBlock), q = Block(ProductBlock), diag = Block(DiagonalBlock);
            int batch = Batch > 0 ? Batch : math.max(1, m_SpringCount);
            for (int s = 0; s < m_SpringCount; s += batch)
                SpringForces.ImplicitFrames(Springs, Rest, x, v, h, s, math.min(s + batch, m_SpringCount), Frames, SlotValues);
            GatherSlots(r);
            for (int s = 0; s < m_SpringCount; s += batch)
                SpringForces.ImplicitDiagonal(Frames, s, math.min(s + batch, m_SpringCount), SlotValues);
            GatherSlots(diag);
            bool pins = false;
            double bb = 0.0, rz = 0.0;
            for (int i = 0; i < m_ParticleCount; i++)
            {
                dv[i] = float3.zero;
                if (w[i] == 0f)
                {
                    pins = true;
                    r[i] = float3.zero;
                }
                diag[i] += m[i];
                z[i] = r[i] / diag[i];
                p[i] = z[i];
                bb += Dot(r[i], r[i]);
                rz += Dot(r[i], z[i]);
            }
            int iterations = 0;
            if (bb > 0.0)
            {
                double tolerance = (double)m_Parameters.CgTolerance * m_Parameters.CgTolerance * bb;
                bool converged = false;
                while (iterations < m_Parameters.CgIterations)
                {
                    iterations++;
                    Product(p, q, batch);
                    double pq = 0.0;
                    for (int i = 0; i < m_ParticleCount; i++)
                        pq += Dot(p[i], q[i]);
                    if (!(pq > 0.0))
                    {
                        converged = true;
                        break;
                    }
                    float alpha = (float)(rz / pq);
                    double rr = 0.0;
                    for (int i = 0; i < m_ParticleCount; i++)
                    {
                        dv[i] += alpha * p[i];
                        r[i] -= alpha * q[i];
                        rr += Dot(r[i], r[i]);
                    }
                    if (rr <= tolerance)
                    {
                        converged = true;
                        break;
                    }
                    double rzNext = 0.0;
                    for (int i = 0; i < m_ParticleCount; i++)
                    {
                        z[i] = r[i] / diag[i];
                        rzNext += Dot(r[i], z[i]);
                    }
                    float beta = (float)(rzNext / rz);
                    rz = rzNext;
                    for (int i = 0; i < m_ParticleCount; i++)
                        p[i] = z[i] + beta * p[i];
                }
                if (!converged)
                    CgUnconverged++;
            }
            MaxCgIterations = math.max(MaxCgIterations, iterations);
            float3 drift = float3.zero;
            if (!pins && totalMass > 0f)
            {
                for (int i = 0; i < m_ParticleCount; i++)
                    drift += m[i] * dv[i];
                drift /= totalMass;
            }
            for (int i = 0; i < m_ParticleCount; i++)
                if (w[i] != 0f)
                    v[i] += dv[i] - drift;
        }

        /// <summary>q = A p = M p + Σ springs' S (p_A − p_B), filtered (zero rows at pinned particles).</summary>
        void Product(ReadOnlySpan<float3> p, Span<float3> q, int batch)
        {
            for (int s = 0; s < m_SpringCount; s += batch)
                SpringForces.ImplicitProduct(Springs, Frames, p, s, math.min(s + batch, m_SpringCount), SlotValues);
            GatherSlots(q);
            ReadOnlySpan<float> m = Masses;
            ReadOnlySpan<float> w = InverseMasses;
            for (int i = 0; i < m_ParticleCount; i++)
                q[i] = w[i] == 0f ? float3.zero : q[i] + m[i] * p[i];
        }

        /// <summary>
        /// XPBD substep (Macklin et al. 2016, Algorithm 1): predict p = x + h v, reset the multipliers, project the
        /// springs colour by colour <see cref="MassSpringParameters.Iterations"/> times
        /// (<see cref="SpringForces.ProjectColor"/>), then v = (p − x)/h, so the shared step's x + h v is p.
        /// </summary>
        void Xpbd(Span<float3> x, Span<float3> v, float h)
        {
            Span<float3> p = Block(PreviousBlock);
            Span<float3> lambda = Frames;
            for (int i = 0; i < m_ParticleCount; i++)
                p[i] = x[i] + h * v[i];
            lambda.Clear();
            ReadOnlySpan<int> offsets = new ReadOnlySpan<int>(m_ColorOffsets, m_ColorCount + 1);
            ReadOnlySpan<int> colorSprings = new ReadOnlySpan<int>(m_ColorSprings, m_SpringCount);
            for (int it = 0; it < m_Parameters.Iterations; it++)
                for (int c = 0; c < m_ColorCount; c++)
                {
                    int end = offsets[c + 1];
                    int batch = Batch > 0 ? Batch : math.max(1, end - offsets[c]);
                    for (int s = offsets[c]; s < end; s += batch)
                        SpringForces.ProjectColor(Springs, colorSprings, Rest, x, InverseMasses, h, s, math.min(s + batch, end), p, lambda);
                }
            float invH = 1f / h;
            for (int i = 0; i < m_ParticleCount; i++)
                v[i] = (p[i] - x[i]) * invH;
        }

        static double Dot(float3 a, float3 b) => (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z;
    }
}

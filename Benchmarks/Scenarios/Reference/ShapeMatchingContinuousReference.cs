using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Float64 reference of the continuous model that <see cref="ShapeMatchingSolver.Step"/> discretises, for a
    /// free body (no contacts):
    /// <code>
    ///   ẍᵢ = a + ω² P(g(x) − x)ᵢ − 2ζω (ẋᵢ − uᵢ)
    /// </code>
    /// <list type="bullet">
    /// <item>gᵢ(x) = Σ_c (1/nᵢ) g_c,i: the average over the particle's clusters of each cluster's goal c_c + T_c q_c,i,
    /// with c_c = Σ w x / Σ w, A_pq = Σ w (x − c_c) qᵀ, weights wᵢ = mᵢ/nᵢ, and T_c = R (rigid: the polar rotation of
    /// A_pq, by Higham's iteration, <see cref="Matrix3d.PolarRotation"/>), R + β·fade·limit·(A − R) + V (linear:
    /// A = A_pq A_qq⁻¹, the strain limited to 1 in the fit's metric and faded out toward a flat or inverted cluster, V the
    /// volume energy's gradient, exactly as <see cref="VolumePreservation.ConservativeLinearGoalTransform"/> specifies), or the quadratic goals of
    /// <see cref="QuadraticGoalsDouble"/> (the float64 statement of the solver's quadratic mode; it has no strain
    /// limit, so the quadratic reference holds while the quadratic strain stays below 1);</item>
    /// <item>P removes from the pull its mass-weighted mean and the rigid rotation δθ × (xᵢ − x_cm) with
    /// I δθ = Σ mᵢ (xᵢ − x_cm) × Δᵢ, as the solver does: for exact rigid and linear goals both are zero
    /// (the pull is momentum- and torque-free), so P only matters for the quadratic goals;</item>
    /// <item>uᵢ = v_cm + Ω × (xᵢ − x_cm), Ω = I⁻¹ L: the body's rigid velocity, which damping leaves alone.</item>
    /// </list>
    /// Integrated by the classical 4th-order Runge–Kutta method at a fixed step, in float64 throughout (the quadratic
    /// goals take float32 positions, given relative to each cluster's centre so their rounding is ~10⁻⁸ of the
    /// cluster size). The solver's per-substep rule (<see cref="OscillatorDiscretization"/>) plays no part here: this
    /// is what the solver converges to as its substep h → 0. Allocation-free per step except in quadratic mode.
    /// </summary>
    public sealed class ShapeMatchingContinuousReference
    {
        readonly ShapeMatchingModelData m_Model;
        readonly ShapeMatchingMode m_Mode;
        readonly double m_Omega, m_Zeta, m_Beta;
        readonly Vector3d m_Acceleration;
        readonly int m_Count;
        readonly double[] m_Mass, m_InverseCount, m_Weight, m_ClusterMass;
        readonly Vector3d[] m_RestOffset;
        readonly Matrix3d[] m_AqqInverse;
        readonly double[] m_LengthSquared;
        readonly bool[] m_LinearValid, m_QuadraticValid;
        readonly float3[][] m_QuadraticRest, m_QuadraticX;
        readonly float[][] m_QuadraticWeight;

        /// <summary>Positions (m, world) and velocities (m/s) of the reference body.</summary>
        public readonly Vector3d[] X, V;
        /// <summary>Time integrated since <see cref="SetState"/> (s).</summary>
        public double Time { get; private set; }

        readonly Vector3d[] m_Goals, m_X2, m_V2, m_A1, m_A2, m_A3, m_A4, m_V3, m_V4;

        /// <param name="parameters">The solver's parameters; their sanitised mode, frequency, damping ratio, β and acceleration define the model.</param>
        public ShapeMatchingContinuousReference(ShapeMatchingModelData model, in ShapeMatchingParameters parameters)
        {
            ShapeMatchingParameters p = parameters.Sanitized();
            m_Model = model;
            m_Mode = p.Mode;
            m_Omega = 2.0 * Math.PI * p.Frequency;
            m_Zeta = p.DampingRatio;
            m_Beta = p.Beta;
            m_Acceleration = (Vector3d)p.Body.Acceleration;
            int n = m_Count = model.ParticleCount;
            m_Mass = new double[n];
            m_InverseCount = new double[n];
            var counts = new int[n];
            foreach (int i in model.ClusterParticles)
                counts[i]++;
            for (int i = 0; i < n; i++)
            {
                m_Mass[i] = model.Masses[i];
                m_InverseCount[i] = counts[i] > 0 ? 1.0 / counts[i] : 0.0;
            }
            int clusters = model.ClusterCount;
            int entries = model.ClusterParticles.Length;
            m_Weight = new double[entries];
            m_RestOffset = new Vector3d[entries];
            m_ClusterMass = new double[clusters];
            m_AqqInverse = new Matrix3d[clusters];
            m_LengthSquared = new double[clusters];
            m_LinearValid = new bool[clusters];
            m_QuadraticValid = new bool[clusters];
            m_QuadraticRest = new float3[clusters][];
            m_QuadraticX = new float3[clusters][];
            m_QuadraticWeight = new float[clusters][];
            for (int c = 0; c < clusters; c++)
            {
                int start = model.ClusterOffsets[c], end = model.ClusterOffsets[c + 1];
                double mass = 0;
                Vector3d center = default;
                for (int k = start; k < end; k++)
                {
                    int i = model.ClusterParticles[k];
                    m_Weight[k] = m_Mass[i] * m_InverseCount[i];
                    mass += m_Weight[k];
                    center += m_Weight[k] * (Vector3d)model.RestPositions[i];
                }
                center = center / mass;
                Matrix3d aqq = Matrix3d.Zero;
                for (int k = start; k < end; k++)
                {
                    m_RestOffset[k] = (Vector3d)model.RestPositions[model.ClusterParticles[k]] - center;
                    aqq += m_Weight[k] * Matrix3d.Outer(m_RestOffset[k], m_RestOffset[k]);
                }
                m_ClusterMass[c] = mass;
                double trace = (aqq.M00 + aqq.M11 + aqq.M22) / 3.0;
                m_LinearValid[c] = trace > 0 && aqq.Determinant > ShapeMatching.PlanarRestShapeThreshold * trace * trace * trace;
                m_AqqInverse[c] = m_LinearValid[c] ? aqq.Inverse : Matrix3d.Identity;
                m_LengthSquared[c] = mass > 0 ? 3.0 * trace / mass : 0.0;
                m_QuadraticValid[c] = m_Mode == ShapeMatchingMode.Quadratic && model.ClusterRest[c].QuadraticValid;
                if (m_QuadraticValid[c])
                {
                    m_QuadraticRest[c] = new float3[end - start];
                    m_QuadraticX[c] = new float3[end - start];
                    m_QuadraticWeight[c] = new float[end - start];
                    for (int k = start; k < end; k++)
                    {
                        m_QuadraticRest[c][k - start] = model.RestPositions[model.ClusterParticles[k]];
                        m_QuadraticWeight[c][k - start] = model.ClusterWeights[k];
                    }
                }
            }
            X = new Vector3d[n];
            V = new Vector3d[n];
            m_Goals = new Vector3d[n];
            m_X2 = new Vector3d[n];
            m_V2 = new Vector3d[n];
            m_V3 = new Vector3d[n];
            m_V4 = new Vector3d[n];
            m_A1 = new Vector3d[n];
            m_A2 = new Vector3d[n];
            m_A3 = new Vector3d[n];
            m_A4 = new Vector3d[n];
        }

        /// <summary>ω = 2πf (rad/s) of the model.</summary>
        public double AngularFrequency => m_Omega;

        /// <summary>Starts from the solver's state: positions relative to <paramref name="origin"/> (the body's <see cref="ParticleBodyStatus.Origin"/>), velocities.</summary>
        public void SetState(ReadOnlySpan<float3> positions, ReadOnlySpan<float3> velocities, float3 origin)
        {
            var o = (Vector3d)origin;
            for (int i = 0; i < m_Count; i++)
            {
                X[i] = o + (Vector3d)positions[i];
                V[i] = (Vector3d)velocities[i];
            }
            Time = 0;
        }

        /// <summary>Integrates <paramref name="duration"/> seconds in <paramref name="steps"/> classical RK4 steps.</summary>
        public void Advance(double duration, int steps)
        {
            double h = duration / steps;
            int n = m_Count;
            for (int s = 0; s < steps; s++)
            {
                Derivative(X, V, m_A1);
                for (int i = 0; i < n; i++)
                {
                    m_X2[i] = X[i] + (0.5 * h) * V[i];
                    m_V2[i] = V[i] + (0.5 * h) * m_A1[i];
                }
                Derivative(m_X2, m_V2, m_A2);
                for (int i = 0; i < n; i++)
                {
                    m_X2[i] = X[i] + (0.5 * h) * m_V2[i];
                    m_V3[i] = V[i] + (0.5 * h) * m_A2[i];
                }
                Derivative(m_X2, m_V3, m_A3);
                for (int i = 0; i < n; i++)
                {
                    m_X2[i] = X[i] + h * m_V3[i];
                    m_V4[i] = V[i] + h * m_A3[i];
                }
                Derivative(m_X2, m_V4, m_A4);
                for (int i = 0; i < n; i++)
                {
                    X[i] = X[i] + (h / 6.0) * (V[i] + 2.0 * m_V2[i] + 2.0 * m_V3[i] + m_V4[i]);
                    V[i] = V[i] + (h / 6.0) * (m_A1[i] + 2.0 * m_A2[i] + 2.0 * m_A3[i] + m_A4[i]);
                }
                Time += h;
            }
        }

        /// <summary>ẍ of the model at positions <paramref name="x"/> and velocities <paramref name="v"/>.</summary>
        public void Derivative(Vector3d[] x, Vector3d[] v, Vector3d[] acceleration)
        {
            int n = m_Count;
            Goals(x, m_Goals);
            // Pull Δ = g − x, then P: mean and rigid rotation removed (no-ops for exact rigid and linear goals).
            double mass = 0;
            Vector3d drift = default, xcm = default, vcm = default;
            double totalMass = 0;
            for (int i = 0; i < n; i++)
            {
                totalMass += m_Mass[i];
                xcm += m_Mass[i] * x[i];
                vcm += m_Mass[i] * v[i];
                if (m_InverseCount[i] > 0)
                {
                    m_Goals[i] = m_Goals[i] - x[i];
                    drift += m_Mass[i] * m_Goals[i];
                    mass += m_Mass[i];
                }
                else
                {
                    m_Goals[i] = default;
                }
            }
            xcm = xcm / totalMass;
            vcm = vcm / totalMass;
            if (mass > 0)
                drift = drift / mass;
            Matrix3d inertia = Matrix3d.Zero;
            Vector3d torque = default, angular = default;
            for (int i = 0; i < n; i++)
            {
                if (m_InverseCount[i] > 0)
                    m_Goals[i] = m_Goals[i] - drift;
                Vector3d r = x[i] - xcm;
                inertia += m_Mass[i] * (r.LengthSquared * Matrix3d.Identity - Matrix3d.Outer(r, r));
                torque += m_Mass[i] * Vector3d.Cross(r, m_Goals[i]);
                angular += m_Mass[i] * Vector3d.Cross(r, v[i] - vcm);
            }
            Matrix3d inverseInertia = inertia.Inverse;
            Vector3d spin = inverseInertia * torque;
            Vector3d rigidSpin = inverseInertia * angular;
            double omega2 = m_Omega * m_Omega, damping = 2.0 * m_Zeta * m_Omega;
            for (int i = 0; i < n; i++)
            {
                Vector3d r = x[i] - xcm;
                Vector3d pull = m_InverseCount[i] > 0 ? m_Goals[i] - Vector3d.Cross(spin, r) : default;
                Vector3d rigidVelocity = vcm + Vector3d.Cross(rigidSpin, r);
                acceleration[i] = m_Acceleration + omega2 * pull - damping * (v[i] - rigidVelocity);
            }
        }

        /// <summary>gᵢ(x): the average over each particle's clusters of the cluster goals (the particle itself when in no cluster).</summary>
        public void Goals(Vector3d[] x, Vector3d[] goals)
        {
            var model = m_Model;
            for (int i = 0; i < m_Count; i++)
                goals[i] = m_InverseCount[i] > 0 ? default : x[i];
            for (int c = 0; c < model.ClusterCount; c++)
            {
                int start = model.ClusterOffsets[c], end = model.ClusterOffsets[c + 1];
                Vector3d center = default;
                for (int k = start; k < end; k++)
                    center += m_Weight[k] * x[model.ClusterParticles[k]];
                center = center / m_ClusterMass[c];
                if (m_QuadraticValid[c])
                {
                    QuadraticClusterGoals(x, goals, c, start, end, center);
                    continue;
                }
                Matrix3d apq = Matrix3d.Zero;
                for (int k = start; k < end; k++)
                    apq += m_Weight[k] * Matrix3d.Outer(x[model.ClusterParticles[k]] - center, m_RestOffset[k]);
                Matrix3d r = apq.PolarRotation();
                Matrix3d t = m_Mode == ShapeMatchingMode.Rigid || !m_LinearValid[c] ? r : LinearGoalTransform(apq * m_AqqInverse[c], r, m_Beta,
                    m_ClusterMass[c] * m_LengthSquared[c], m_AqqInverse[c]);
                for (int k = start; k < end; k++)
                {
                    int i = model.ClusterParticles[k];
                    goals[i] += m_InverseCount[i] * (center + t * m_RestOffset[k]);
                }
            }
        }

        void QuadraticClusterGoals(Vector3d[] x, Vector3d[] goals, int c, int start, int end, Vector3d center)
        {
            var model = m_Model;
            float3[] local = m_QuadraticX[c];
            // Goals are translation-equivariant: pass positions relative to the cluster centre so float32 keeps their detail.
            for (int k = start; k < end; k++)
            {
                Vector3d p = x[model.ClusterParticles[k]] - center;
                local[k - start] = new float3((float)p.X, (float)p.Y, (float)p.Z);
            }
            double[,] g = QuadraticGoalsDouble.Goals(m_QuadraticRest[c], local, m_QuadraticWeight[c], (float)m_Beta);
            for (int k = start; k < end; k++)
            {
                int i = model.ClusterParticles[k];
                goals[i] += m_InverseCount[i] * (center + new Vector3d(g[k - start, 0], g[k - start, 1], g[k - start, 2]));
            }
        }

        /// <summary>
        /// The linear mode's goal transform in float64, as <see cref="VolumePreservation.ConservativeLinearGoalTransform"/>
        /// states it: R when det(A / max|Aᵢⱼ|) is at or below the floor; otherwise R + w·limit·(A − R) + V with w = β·fade,
        /// limit = min(1, ε_max/ε) for the strain ε² = 3 tr((A − R) A_qq (A − R)ᵀ) / (M L²) and ε_max =
        /// <see cref="VolumePreservation.MaxGoalStrain"/>, fade = saturate((det − floor) / (9·floor)) and
        /// V = −(w/9)(det A − 1) M L² cof(A) A_qq⁻¹.
        /// </summary>
        public static Matrix3d LinearGoalTransform(in Matrix3d a, in Matrix3d r, double beta, double massLengthSquared, in Matrix3d aqqInverse)
        {
            const double floor = VolumePreservation.DefaultRelativeDeterminantFloor;
            double scale = a.MaxAbs;
            if (!(scale > 0))
                return r;
            double det = ((1.0 / scale) * a).Determinant;
            if (!(det > floor))
                return r;
            // The solver's weight of the β part (1 away from flat or inverted clusters; its own piecewise-linear rule).
            double weight = Math.Min(1.0, Math.Max(0.0, beta)) * VolumePreservation.BetaFade((float)det);
            Matrix3d strain = a - r;
            double strainNorm = Math.Sqrt(3.0 * Matrix3d.Dot(strain * aqqInverse.Inverse, strain) / massLengthSquared);
            double limit = strainNorm > VolumePreservation.MaxGoalStrain ? VolumePreservation.MaxGoalStrain / strainNorm : 1.0;
            double j = a.Determinant;
            Matrix3d cofactor = j * a.Inverse.Transpose;
            return r + (weight * limit) * strain + (-weight / 9.0 * (j - 1.0) * massLengthSquared) * (cofactor * aqqInverse);
        }
    }
}

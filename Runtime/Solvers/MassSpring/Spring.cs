namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One spring of a mass-spring network (Teschner, Heidelberger, Müller &amp; Gross 2003, §3.1): a linear spring
    /// between particles <see cref="A"/> and <see cref="B"/> with a dashpot along it. The force on A is
    /// f_A = (k (L − L₀) + c (v_B − v_A)·n) n with d = x_B − x_A, L = ‖d‖, n = d / L, and f_B = −f_A.
    /// </summary>
    public struct Spring
    {
        /// <summary>First particle.</summary>
        public int A;
        /// <summary>Second particle.</summary>
        public int B;
        /// <summary>Rest length L₀ (m), from the rest shape.</summary>
        public float RestLength;
        /// <summary>Stiffness k (N/m).</summary>
        public float Stiffness;
        /// <summary>Damping c (N·s/m) of the dashpot along the spring.</summary>
        public float Damping;

        public Spring(int a, int b, float restLength, float stiffness, float damping)
        {
            A = a;
            B = b;
            RestLength = restLength;
            Stiffness = stiffness;
            Damping = damping;
        }
    }
}

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Whether a step's parameters had to be replaced: every method's step runs on <c>parameters.Sanitized()</c> (invalid
    /// values → the default, values beyond a limit → the limit) and says so in its report (<see cref="ParticleStepReport.ParametersReplaced"/>),
    /// so the values bake-time validation rejects are never changed silently at run time either.
    /// </summary>
    public static class SanitizedParameters
    {
        /// <summary>True when <paramref name="sanitized"/> differs from <paramref name="original"/> in any byte (a replaced field).</summary>
        public static unsafe bool Differ<T>(in T original, in T sanitized) where T : unmanaged
        {
            fixed (T* a = &original)
            fixed (T* b = &sanitized)
            {
                byte* x = (byte*)a, y = (byte*)b;
                for (int i = 0; i < sizeof(T); i++)
                    if (x[i] != y[i])
                        return true;
            }
            return false;
        }
    }
}

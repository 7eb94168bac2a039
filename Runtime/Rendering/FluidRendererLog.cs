using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>Warnings the renderer gives once per cause rather than every frame.</summary>
    static class FluidRendererLog
    {
        const string k_Prefix = "Fluid renderer: ";

        /// <summary>Logs <paramref name="message"/> unless <paramref name="logged"/> is already set, then sets it.</summary>
        public static void WarnOnce(ref bool logged, string message)
        {
            if (logged)
                return;
            logged = true;
            Debug.LogWarning(k_Prefix + message);
        }

        public static void Warn(string message) => Debug.LogWarning(k_Prefix + message);
    }
}

using System.Linq;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// Runtime/Solvers is the pure-math reference that also compiles and runs outside Unity, so its compiled
    /// assembly must not depend on the engine, the editor or Entities.
    /// </summary>
    public class SolversAssemblyTests
    {
        static readonly string[] k_ForbiddenPrefixes = { "UnityEngine", "UnityEditor", "Unity.Entities" };

        /// <summary>
        /// From Unity 6.5 Unity.Mathematics is a type-forwarding assembly onto this engine module, so a compiled
        /// reference to it is the Mathematics dependency the Solvers assembly is allowed, not an engine dependency.
        /// </summary>
        const string k_MathematicsModule = "UnityEngine.MathematicsModule";

        [Test]
        public void SolversAssembly_ReferencesNoUnityEngine()
        {
            var referenced = typeof(RotationExtraction).Assembly.GetReferencedAssemblies()
                .Select(a => a.Name)
                .Where(n => n != k_MathematicsModule)
                .ToArray();

            foreach (var prefix in k_ForbiddenPrefixes)
                Assert.That(referenced, Has.None.StartWith(prefix),
                    $"SoftBodyDynamics.Solvers must not reference {prefix}*; it references: {string.Join(", ", referenced)}");
        }
    }
}

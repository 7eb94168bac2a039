using System;
using System.Collections.Generic;
using System.Linq;
using Mono.Cecil;

namespace SoftBodyDynamics.Tools.BurstCheck
{
    /// <summary>
    /// Follows every method reachable from a Burst entry point — a method marked [BurstCompile], or the Execute methods
    /// of a struct marked [BurstCompile] (a job) — through the package's own assemblies, and collects what
    /// <see cref="BurstRules"/> rejects. A call through an interface declared in the package follows every package
    /// struct that implements it (a generic job's type argument). Calls out of the package must be ones Burst supports.
    /// </summary>
    sealed class BurstChecker
    {
        public const string BurstCompileAttribute = "Unity.Burst.BurstCompileAttribute";

        readonly HashSet<string> m_PackageAssemblies;
        readonly List<TypeDefinition> m_PackageTypes;
        readonly HashSet<string> m_Visited = new HashSet<string>(StringComparer.Ordinal);
        readonly Queue<(MethodDefinition Method, string Path)> m_Work = new Queue<(MethodDefinition, string)>();

        /// <summary>Each problem: the entry point's path to the method, and what is wrong there.</summary>
        public readonly List<(string Path, string Problem)> Problems = new List<(string, string)>();
        public readonly List<string> EntryPoints = new List<string>();
        public int MethodsChecked => m_Visited.Count;

        public BurstChecker(IReadOnlyList<AssemblyDefinition> package)
        {
            m_PackageAssemblies = new HashSet<string>(package.Select(a => a.Name.Name), StringComparer.Ordinal);
            m_PackageTypes = package.SelectMany(a => a.MainModule.GetTypes()).ToList();
        }

        public void Run()
        {
            foreach (TypeDefinition type in m_PackageTypes)
            {
                bool burstType = HasBurstCompile(type.CustomAttributes);
                foreach (MethodDefinition method in type.Methods)
                    if (method.HasBody && (HasBurstCompile(method.CustomAttributes) || (burstType && type.IsValueType && method.Name == "Execute")))
                    {
                        EntryPoints.Add(Name(method));
                        Enqueue(method, Name(method));
                    }
                if (burstType && type.IsValueType)
                    foreach (FieldDefinition field in type.Fields)
                        if (!field.IsStatic && BurstRules.IsManaged(field.FieldType))
                            Problems.Add((type.FullName, $"job field {field.Name} of the managed type {field.FieldType.FullName}"));
            }
            while (m_Work.Count > 0)
            {
                var (method, path) = m_Work.Dequeue();
                foreach (string problem in BurstRules.Check(method, target => Follow(target, path)))
                    Problems.Add((path, problem));
            }
        }

        static bool HasBurstCompile(IEnumerable<CustomAttribute> attributes) =>
            attributes.Any(a => a.AttributeType.FullName == BurstCompileAttribute);

        static string Name(MethodReference method) => $"{method.DeclaringType.FullName}.{method.Name}";

        void Enqueue(MethodDefinition method, string path)
        {
            if (method.HasBody && m_Visited.Add(method.FullName))
                m_Work.Enqueue((method, path));
        }

        void Follow(MethodReference target, string path)
        {
            MethodReference element = target is GenericInstanceMethod generic ? generic.ElementMethod : target;
            string assembly = element.DeclaringType.Scope switch
            {
                AssemblyNameReference name => name.Name,
                ModuleDefinition module => module.Assembly.Name.Name,
                _ => "",
            };
            if (!m_PackageAssemblies.Contains(assembly) || BurstRules.IsLog(element))
            {
                if (!BurstRules.IsSupportedExternal(element))
                    Problems.Add((path, $"call to {element.DeclaringType.FullName}.{element.Name}, which Burst does not support"));
                return;
            }
            MethodDefinition definition;
            try
            {
                definition = element.Resolve();
            }
            catch (AssemblyResolutionException)
            {
                definition = null;
            }
            if (definition == null)
            {
                Problems.Add((path, $"unresolved call to {element.FullName}"));
                return;
            }
            string next = $"{path} → {Name(definition)}";
            if (definition.DeclaringType.IsInterface)
            {
                foreach (MethodDefinition implementation in Implementations(definition))
                    Enqueue(implementation, $"{path} → {Name(implementation)}");
                return;
            }
            Enqueue(definition, next);
        }

        /// <summary>The methods of package structs that implement <paramref name="interfaceMethod"/>.</summary>
        IEnumerable<MethodDefinition> Implementations(MethodDefinition interfaceMethod)
        {
            TypeDefinition declaring = interfaceMethod.DeclaringType;
            foreach (TypeDefinition type in m_PackageTypes)
            {
                if (!type.IsValueType || !type.Interfaces.Any(i => i.InterfaceType.GetElementType().FullName == declaring.FullName))
                    continue;
                foreach (MethodDefinition method in type.Methods)
                    if (method.Name == interfaceMethod.Name || method.Overrides.Any(o => o.Name == interfaceMethod.Name && o.DeclaringType.GetElementType().FullName == declaring.FullName))
                        yield return method;
            }
        }
    }
}

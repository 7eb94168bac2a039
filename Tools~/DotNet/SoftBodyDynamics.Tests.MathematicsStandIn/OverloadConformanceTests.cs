using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.MathematicsStandIn
{
    /// <summary>
    /// The stand-in against the real package's list of overloads (Tools~/UnityApi/Unity.Mathematics/reference-overloads.txt,
    /// written from com.unity.mathematics 1.3.2's source): a call Unity binds to an overload the stand-in lacks must not
    /// compile here, or it would silently bind to another overload through an implicit conversion (math.min(long, long)
    /// to the float one, math.length(float) to length(float2)) and the .NET build would run other arithmetic than Unity.
    /// </summary>
    public class OverloadConformanceTests
    {
        sealed class Overload
        {
            public string Line, Type, Name, Target;
            public string[] Parameters;
        }

        static readonly Dictionary<string, Type> s_Builtin = new Dictionary<string, Type>
        {
            ["bool"] = typeof(bool), ["byte"] = typeof(byte), ["sbyte"] = typeof(sbyte), ["short"] = typeof(short), ["ushort"] = typeof(ushort),
            ["int"] = typeof(int), ["uint"] = typeof(uint), ["long"] = typeof(long), ["ulong"] = typeof(ulong), ["float"] = typeof(float),
            ["double"] = typeof(double), ["string"] = typeof(string), ["object"] = typeof(object),
        };

        // C# implicit numeric conversions (ECMA-334 §10.2.3).
        static readonly Dictionary<Type, Type[]> s_Widening = new Dictionary<Type, Type[]>
        {
            [typeof(sbyte)] = new[] { typeof(short), typeof(int), typeof(long), typeof(float), typeof(double) },
            [typeof(byte)] = new[] { typeof(short), typeof(ushort), typeof(int), typeof(uint), typeof(long), typeof(ulong), typeof(float), typeof(double) },
            [typeof(short)] = new[] { typeof(int), typeof(long), typeof(float), typeof(double) },
            [typeof(ushort)] = new[] { typeof(int), typeof(uint), typeof(long), typeof(ulong), typeof(float), typeof(double) },
            [typeof(int)] = new[] { typeof(long), typeof(float), typeof(double) },
            [typeof(uint)] = new[] { typeof(long), typeof(ulong), typeof(float), typeof(double) },
            [typeof(long)] = new[] { typeof(float), typeof(double) },
            [typeof(ulong)] = new[] { typeof(float), typeof(double) },
            [typeof(float)] = new[] { typeof(double) },
        };

        static readonly Assembly s_StandIn = typeof(float3).Assembly;

        static string ReferencePath()
        {
            for (var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); dir != null; dir = dir.Parent)
            {
                string path = Path.Combine(dir.FullName, "Tools~", "UnityApi", "Unity.Mathematics", "reference-overloads.txt");
                if (File.Exists(path))
                    return path;
            }
            throw new FileNotFoundException("Tools~/UnityApi/Unity.Mathematics/reference-overloads.txt above " + TestContext.CurrentContext.TestDirectory);
        }

        static IEnumerable<Overload> Reference()
        {
            foreach (string raw in File.ReadLines(ReferencePath()))
            {
                string line = raw.Trim();
                if (line.Length == 0 || line[0] == '#')
                    continue;
                int open = line.IndexOf('('), close = line.IndexOf(')'), dot = line.IndexOf('.');
                string args = line.Substring(open + 1, close - open - 1);
                int arrow = line.IndexOf("->", close, StringComparison.Ordinal);
                yield return new Overload
                {
                    Line = line, Type = line.Substring(0, dot), Name = line.Substring(dot + 1, open - dot - 1),
                    Parameters = args.Length == 0 ? Array.Empty<string>() : args.Split(',').Select(a => a.Trim()).ToArray(),
                    Target = arrow > 0 ? line.Substring(arrow + 2).Trim() : null,
                };
            }
        }

        /// <summary>The stand-in's or the runtime's type of a C# type name; null when the stand-in has no such type.</summary>
        static Type Resolve(string name) =>
            s_Builtin.TryGetValue(name, out Type t) ? t : s_StandIn.GetType("Unity.Mathematics." + name, false);

        static IEnumerable<MethodInfo> StaticMethods(Type type, string name) =>
            type.GetMethods(BindingFlags.Public | BindingFlags.Static).Where(m => m.Name == name);

        static bool Exact(MethodInfo m, Type[] parameters, Type target) =>
            m.GetParameters().Select(p => p.ParameterType.IsByRef ? p.ParameterType.GetElementType() : p.ParameterType).SequenceEqual(parameters)
            && (target == null || m.ReturnType == target);

        /// <summary>An implicit conversion from <paramref name="from"/> to <paramref name="to"/> in the stand-in: identity, numeric, or user-defined after a numeric one.</summary>
        static bool Converts(Type from, Type to)
        {
            if (from == to || (s_Widening.TryGetValue(from, out Type[] wider) && wider.Contains(to)))
                return true;
            var sources = new List<Type> { from };
            if (wider != null)
                sources.AddRange(wider);
            foreach (Type owner in new[] { from, to }.Where(t => t.Assembly == s_StandIn))
                foreach (MethodInfo op in StaticMethods(owner, "op_Implicit"))
                    if (op.ReturnType == to && sources.Contains(op.GetParameters()[0].ParameterType))
                        return true;
            return false;
        }

        [Test]
        public void EveryOverloadUnityHas_IsInTheStandIn_OrDoesNotCompileThere()
        {
            var rebinding = new List<string>();
            int checkedCount = 0;
            foreach (Overload r in Reference())
            {
                Type owner = Resolve(r.Type);
                Type[] parameters = r.Parameters.Select(Resolve).ToArray();
                Type target = r.Target != null ? Resolve(r.Target) : null;
                if (owner == null || parameters.Any(p => p == null) || (r.Target != null && target == null))
                    continue;
                checkedCount++;
                if (StaticMethods(owner, r.Name).Any(m => Exact(m, parameters, target)))
                    continue;
                // Conversions the stand-in lacks make the code that needs them fail to compile: no other can stand in.
                if (r.Name == "op_Implicit" || r.Name == "op_Explicit")
                    continue;
                // C# looks for an operator in both operands' types, for a method in the named type.
                IEnumerable<Type> owners = r.Name.StartsWith("op_", StringComparison.Ordinal)
                    ? parameters.Where(p => p.Assembly == s_StandIn).Append(owner).Distinct()
                    : new[] { owner };
                MethodInfo other = owners.SelectMany(o => StaticMethods(o, r.Name)).FirstOrDefault(m =>
                {
                    ParameterInfo[] ps = m.GetParameters();
                    return ps.Length == parameters.Length && ps.Select((p, i) => Converts(parameters[i], p.ParameterType)).All(ok => ok);
                });
                if (other != null)
                    rebinding.Add($"{r.Line} binds to {other.DeclaringType.Name}.{other.Name}({string.Join(", ", other.GetParameters().Select(p => p.ParameterType.Name))})");
            }
            Assert.That(checkedCount, Is.GreaterThan(200), "the reference list was read");
            Assert.That(rebinding, Is.Empty, "overloads Unity has that the stand-in lacks, which a call would silently replace:\n" + string.Join("\n", rebinding));
        }
    }
}

using System;
using System.Collections.Generic;
using System.Linq;
using Mono.Cecil;
using Mono.Cecil.Cil;

namespace SoftBodyDynamics.Tools.BurstCheck
{
    /// <summary>
    /// What Burst's High Performance C# subset does not compile, as the Burst 1.8 manual states it: no managed objects or
    /// arrays (csharp-type-support.html; static read-only arrays excepted), no boxing, no catch (try/finally only;
    /// csharp-hpc-overview.html), strings only as the literal message of a simple throw or
    /// as a literal, or string.Format of a literal with value-type arguments, passed to Debug.Log, LogWarning or LogError
    /// (csharp-string-support.html), no
    /// writes to static fields and no mutable static reads (csharp-static-read-only-support.html), no delegates
    /// (function pointers instead), and of the base library only System.Math, IntPtr, Interlocked, Thread.MemoryBarrier,
    /// Volatile (csharp-system-support.html), Span types (csharp-type-support.html) and the primitive types.
    /// </summary>
    static class BurstRules
    {
        /// <summary>
        /// Unity namespaces whose types Burst code calls (their own Burst compatibility is Unity's); NativeArray lives in
        /// UnityEngine.CoreModule, so the namespace decides, not the assembly.
        /// </summary>
        static readonly string[] s_UnityNamespaces =
        {
            "Unity.Mathematics", "Unity.Collections", "Unity.Burst", "Unity.Entities", "Unity.Transforms", "Unity.Jobs", "Unity.Physics",
        };

        /// <summary>Base-library types Burst supports (full names).</summary>
        static readonly HashSet<string> s_SystemTypes = new HashSet<string>(StringComparer.Ordinal)
        {
            "System.Math", "System.IntPtr", "System.UIntPtr", "System.Threading.Interlocked", "System.Threading.Volatile",
            "System.Span`1", "System.ReadOnlySpan`1", "System.Runtime.CompilerServices.Unsafe",
            "System.Boolean", "System.Byte", "System.SByte", "System.Int16", "System.UInt16", "System.Int32", "System.UInt32",
            "System.Int64", "System.UInt64", "System.Single", "System.Double",
        };

        /// <summary>True when a call to <paramref name="method"/>, declared outside the package, is one Burst compiles.</summary>
        public static bool IsSupportedExternal(MethodReference method)
        {
            TypeReference type = method.DeclaringType.GetElementType();
            string ns = OutermostNamespace(type);
            foreach (string unity in s_UnityNamespaces)
                if (ns == unity || ns.StartsWith(unity + ".", StringComparison.Ordinal))
                    return true;
            if (type.FullName == "System.Threading.Thread")
                return method.Name == "MemoryBarrier";
            if (IsLog(method))
                return true;
            // Exception constructors appear only in a checked `throw new X("literal")` (see Check).
            if (method.Name == ".ctor" && IsException(type))
                return true;
            // string int.ToString() and the like: a supported type, but a managed result or argument.
            if (IsManaged(method.ReturnType) && method.ReturnType.MetadataType != MetadataType.Void || method.Parameters.Any(p => IsManaged(p.ParameterType)))
                return false;
            return s_SystemTypes.Contains(type.FullName);
        }

        /// <summary>Debug.Log, LogWarning or LogError (object): the logging Burst supports.</summary>
        public static bool IsLog(MethodReference method) =>
            method.DeclaringType.FullName == "UnityEngine.Debug" && method.Parameters.Count == 1
            && (method.Name == "Log" || method.Name == "LogWarning" || method.Name == "LogError");

        static bool IsFormat(Instruction i) =>
            i.OpCode == OpCodes.Call && i.Operand is MethodReference m && m.DeclaringType.FullName == "System.String" && m.Name == "Format";

        /// <summary>
        /// The instructions that build a supported log message: a literal passed straight to a log call, or a
        /// string.Format call of a literal and everything from that literal to the call (boxing its value-type
        /// arguments, the object[] of four or more).
        /// </summary>
        static HashSet<Instruction> LogMessages(MethodBody body)
        {
            var inside = new HashSet<Instruction>();
            foreach (Instruction call in body.Instructions)
            {
                if (!(call.OpCode == OpCodes.Call && call.Operand is MethodReference m && IsLog(m)) || call.Previous == null)
                    continue;
                Instruction message = call.Previous;
                if (message.OpCode == OpCodes.Ldstr)
                {
                    inside.Add(message);
                    continue;
                }
                if (!IsFormat(message))
                    continue;
                Instruction literal = message.Previous;
                while (literal != null && literal.OpCode != OpCodes.Ldstr)
                    literal = literal.Previous;
                for (Instruction i = literal; i != null && i != call; i = i.Next)
                    inside.Add(i);
            }
            return inside;
        }

        static string OutermostNamespace(TypeReference type)
        {
            while (type.DeclaringType != null)
                type = type.DeclaringType;
            return type.Namespace;
        }

        /// <summary>True for System.Exception and the types derived from it.</summary>
        public static bool IsException(TypeReference type)
        {
            for (TypeDefinition t = Resolve(type); t != null; t = Resolve(t.BaseType))
                if (t.FullName == "System.Exception")
                    return true;
            return false;
        }

        /// <summary>True for a class, interface, array, string or object: anything the garbage collector manages.</summary>
        public static bool IsManaged(TypeReference type)
        {
            if (type is ByReferenceType byRef)
                return IsManaged(byRef.ElementType);
            if (type is IModifierType modified)
                return IsManaged(modified.ElementType);
            if (type is PointerType || type.IsGenericParameter || type.IsValueType)
                return false;
            if (type.IsArray || type.MetadataType == MetadataType.String || type.MetadataType == MetadataType.Object)
                return true;
            TypeDefinition definition = Resolve(type);
            return definition == null || !definition.IsValueType;
        }

        public static TypeDefinition Resolve(TypeReference type)
        {
            if (type == null)
                return null;
            try
            {
                return type.GetElementType().Resolve();
            }
            catch (AssemblyResolutionException)
            {
                return null;
            }
        }

        /// <summary>
        /// The problems of one method body, each as "what (where)"; <paramref name="onCall"/> gets every method it calls
        /// or whose address it takes, for the walk to follow.
        /// </summary>
        public static IEnumerable<string> Check(MethodDefinition method, Action<MethodReference> onCall)
        {
            foreach (ExceptionHandler handler in method.Body.ExceptionHandlers)
                if (handler.HandlerType != ExceptionHandlerType.Finally)
                    yield return $"try/{handler.HandlerType.ToString().ToLowerInvariant()}: Burst supports try/finally only";
            foreach (ParameterDefinition parameter in method.Parameters)
                if (IsManaged(parameter.ParameterType))
                    yield return $"managed parameter {parameter.Name} of type {parameter.ParameterType.FullName}";
            if (method.ReturnType.MetadataType != MetadataType.Void && IsManaged(method.ReturnType))
                yield return $"returns the managed type {method.ReturnType.FullName}";
            HashSet<Instruction> logMessages = LogMessages(method.Body);
            foreach (Instruction instruction in method.Body.Instructions)
            {
                string problem = logMessages.Contains(instruction) ? CheckLogMessage(instruction, onCall) : Check(instruction, onCall);
                if (problem != null)
                    yield return $"{problem} (IL_{instruction.Offset:x4})";
            }
        }

        static string Check(Instruction instruction, Action<MethodReference> onCall)
        {
            OpCode op = instruction.OpCode;
            if (op == OpCodes.Newarr)
                return $"new managed array of {((TypeReference)instruction.Operand).FullName}";
            if (op == OpCodes.Box)
                return $"boxing of {((TypeReference)instruction.Operand).FullName}";
            if (op == OpCodes.Isinst || op == OpCodes.Castclass)
                return $"managed type test or cast to {((TypeReference)instruction.Operand).FullName}";
            if (op == OpCodes.Ldftn || op == OpCodes.Ldvirtftn)
                return $"delegate to {((MethodReference)instruction.Operand).FullName} (Burst uses function pointers)";
            if (op == OpCodes.Stsfld || op == OpCodes.Ldsflda)
                return $"static field {((FieldReference)instruction.Operand).FullName} written or taken by reference";
            if (op == OpCodes.Ldsfld)
            {
                var field = (FieldReference)instruction.Operand;
                FieldDefinition definition = field.Resolve();
                if (definition != null && !definition.IsInitOnly && !definition.IsLiteral)
                    return $"mutable static field {field.FullName}";
                return null;
            }
            if (op == OpCodes.Ldstr)
                return ThrowsNext(instruction, 8) ? null : $"string \"{instruction.Operand}\" outside a throw's literal message";
            if (op == OpCodes.Newobj)
            {
                var constructor = (MethodReference)instruction.Operand;
                if (IsManaged(constructor.DeclaringType))
                {
                    if (IsException(constructor.DeclaringType) && instruction.Next?.OpCode == OpCodes.Throw)
                        return null;
                    return $"new managed object {constructor.DeclaringType.FullName}";
                }
                onCall(constructor);
                return null;
            }
            if (op == OpCodes.Call || op == OpCodes.Callvirt)
            {
                var target = (MethodReference)instruction.Operand;
                bool constrained = instruction.Previous?.OpCode == OpCodes.Constrained;
                if (target.HasThis && !constrained && IsManaged(target.DeclaringType) && !IsInterface(target.DeclaringType))
                    return $"method of a managed object {target.FullName}";
                onCall(target);
                return null;
            }
            return null;
        }

        /// <summary>Inside a log message: the literal, boxing of primitives, the object[] and string.Format are allowed.</summary>
        static string CheckLogMessage(Instruction instruction, Action<MethodReference> onCall)
        {
            OpCode op = instruction.OpCode;
            if (op == OpCodes.Ldstr || IsFormat(instruction))
                return null;
            if (op == OpCodes.Box)
            {
                var type = (TypeReference)instruction.Operand;
                return type.IsPrimitive ? null : $"log argument of type {type.FullName} (Burst formats primitive values only)";
            }
            if (op == OpCodes.Newarr && ((TypeReference)instruction.Operand).MetadataType == MetadataType.Object)
                return null;
            return Check(instruction, onCall);
        }

        static bool IsInterface(TypeReference type) => Resolve(type)?.IsInterface == true;

        /// <summary>True when a newobj of an exception followed by throw comes within <paramref name="window"/> instructions.</summary>
        static bool ThrowsNext(Instruction instruction, int window)
        {
            Instruction i = instruction.Next;
            for (int k = 0; k < window && i != null; k++, i = i.Next)
            {
                if (i.OpCode == OpCodes.Newobj && IsException(((MethodReference)i.Operand).DeclaringType))
                    return i.Next?.OpCode == OpCodes.Throw;
                if (i.OpCode == OpCodes.Call || i.OpCode == OpCodes.Callvirt)
                    return false;
            }
            return false;
        }
    }
}

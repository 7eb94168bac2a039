using System;

#pragma warning disable CS0660, CS0661 // Unity's Object defines == and != (documented); Equals/GetHashCode are not used here.

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Object.html
    public class Object
    {
        // https://docs.unity3d.com/ScriptReference/Object-name.html
        public string name { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Object.Destroy.html
        public static void Destroy(Object obj) => throw null;

        // https://docs.unity3d.com/ScriptReference/Object.DestroyImmediate.html
        public static void DestroyImmediate(Object obj, bool allowDestroyingAssets = false) => throw null;

        // https://docs.unity3d.com/ScriptReference/Object-operator_Object.html
        public static implicit operator bool(Object exists) => throw null;

        // https://docs.unity3d.com/ScriptReference/Object-operator_eq.html
        public static bool operator ==(Object x, Object y) => throw null;

        // https://docs.unity3d.com/ScriptReference/Object-operator_ne.html
        public static bool operator !=(Object x, Object y) => throw null;
    }
}

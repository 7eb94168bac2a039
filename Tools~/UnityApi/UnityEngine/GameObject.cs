using System;
using System.Collections.Generic;

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/GameObject.html
    public sealed class GameObject : Object
    {
        // https://docs.unity3d.com/ScriptReference/GameObject-ctor.html
        public GameObject(string name) => throw null;

        // https://docs.unity3d.com/ScriptReference/GameObject-transform.html
        public Transform transform => throw null;

        // https://docs.unity3d.com/ScriptReference/GameObject-tag.html
        public string tag { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/GameObject.AddComponent.html
        public T AddComponent<T>() where T : Component => throw null;

        // https://docs.unity3d.com/ScriptReference/GameObject.GetComponent.html
        public T GetComponent<T>() => throw null;

        // https://docs.unity3d.com/ScriptReference/GameObject.GetComponents.html
        public T[] GetComponents<T>() => throw null;

        // https://docs.unity3d.com/ScriptReference/GameObject.SetActive.html
        public void SetActive(bool value) => throw null;

        // https://docs.unity3d.com/ScriptReference/GameObject.CreatePrimitive.html
        public static GameObject CreatePrimitive(PrimitiveType type) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/PrimitiveType.html (values UNCONFIRMED; names from the page)
    public enum PrimitiveType
    {
        Sphere = 0,
        Capsule = 1,
        Cylinder = 2,
        Cube = 3,
        Plane = 4,
        Quad = 5,
    }
}

using System;

namespace UnityEditor
{
    // https://docs.unity3d.com/ScriptReference/AssetDatabase.html
    public sealed class AssetDatabase
    {
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.LoadAssetAtPath.html
        public static UnityEngine.Object LoadAssetAtPath(string assetPath, Type type) => throw null;
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.CreateAsset.html
        public static void CreateAsset(UnityEngine.Object asset, string path) => throw null;
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.FindAssets.html
        public static string[] FindAssets(string filter) => throw null;
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.GUIDToAssetPath.html
        public static string GUIDToAssetPath(string guid) => throw null;
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.IsValidFolder.html
        public static bool IsValidFolder(string path) => throw null;
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.CreateFolder.html
        public static string CreateFolder(string parentFolder, string newFolderName) => throw null;
        // https://docs.unity3d.com/ScriptReference/AssetDatabase.SaveAssets.html
        public static void SaveAssets() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/SceneAsset.html
    public class SceneAsset : UnityEngine.Object
    {
    }

    // https://docs.unity3d.com/ScriptReference/MenuItem.html
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/MenuItem-ctor.html
        public MenuItem(string itemName) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Selection.html
    public class Selection
    {
        // https://docs.unity3d.com/ScriptReference/Selection-activeObject.html
        public static UnityEngine.Object activeObject { get => throw null; set => throw null; }
    }
}

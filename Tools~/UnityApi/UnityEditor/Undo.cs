namespace UnityEditor
{
    // https://docs.unity3d.com/ScriptReference/Undo.html
    public class Undo
    {
        // https://docs.unity3d.com/ScriptReference/Undo.RecordObjects.html
        public static void RecordObjects(UnityEngine.Object[] objectsToUndo, string name) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/EditorUtility.html
    public class EditorUtility
    {
        // https://docs.unity3d.com/ScriptReference/EditorUtility.DisplayDialog.html
        public static bool DisplayDialog(string title, string message, string ok, string cancel = "") => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/PrefabUtility.html
    public sealed class PrefabUtility
    {
        // https://docs.unity3d.com/ScriptReference/PrefabUtility.SaveAsPrefabAsset.html
        // (public static GameObject SaveAsPrefabAsset(GameObject instanceRoot, string assetPath))
        public static UnityEngine.GameObject SaveAsPrefabAsset(UnityEngine.GameObject instanceRoot, string assetPath) => throw null;

        // https://docs.unity3d.com/ScriptReference/PrefabUtility.RecordPrefabInstancePropertyModifications.html
        public static void RecordPrefabInstancePropertyModifications(UnityEngine.Object targetObject) => throw null;
    }
}

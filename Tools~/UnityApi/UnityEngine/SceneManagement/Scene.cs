namespace UnityEngine.SceneManagement
{
    // https://docs.unity3d.com/ScriptReference/SceneManagement.Scene.html
    public struct Scene
    {
    }

    // https://docs.unity3d.com/ScriptReference/SceneManagement.SceneManager.html
    public class SceneManager
    {
        // https://docs.unity3d.com/ScriptReference/SceneManagement.SceneManager.MoveGameObjectToScene.html
        public static void MoveGameObjectToScene(GameObject go, Scene scene) => throw null;
    }
}

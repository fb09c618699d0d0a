// Reads "java.class.name fingerprint" lines (the C++ hashes, from
// print_type_hashes) on stdin and checks that lcm-spy's type database finds
// each class by that fingerprint, and that the class's LCM_FINGERPRINT agrees.
import java.io.BufferedReader;
import java.io.InputStreamReader;

import lcm.spy.LCMTypeDatabase;

public class FingerprintCheck {
    public static void main(String[] args) throws Exception {
        LCMTypeDatabase db = new LCMTypeDatabase();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in));
        int checked = 0, bad = 0;
        for (String line; (line = in.readLine()) != null; ) {
            String[] parts = line.trim().split("\\s+");
            if (parts.length != 2) continue;
            String name = parts[0];
            long hash = Long.parseLong(parts[1]);
            Class<?> found = db.getClassByFingerprint(hash);
            checked++;
            if (found == null || !found.getName().equals(name)) {
                System.out.println("FAIL " + name + ": lcm-spy finds " + found + " by fingerprint " + hash);
                bad++;
                continue;
            }
            long javaHash = found.getField("LCM_FINGERPRINT").getLong(null);
            if (javaHash != hash) {
                System.out.println("FAIL " + name + ": Java LCM_FINGERPRINT " + javaHash + " != C++ " + hash);
                bad++;
            } else {
                System.out.println("ok   " + name + " " + hash);
            }
        }
        System.out.println(checked + " types checked, " + bad + " failed");
        System.exit(bad == 0 && checked > 0 ? 0 : 1);
    }
}

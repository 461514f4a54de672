// Reads (a, b) pairs of binary32 words and writes a <= b, one line each.
module tb_float_le;
    reg [63:0] vectors [0:65535];
    reg [31:0] a, b;
    wire le;
    integer count, v, out;
    float_le dut (.a(a), .b(b), .le(le));
    initial begin
        if (!$value$plusargs("count=%d", count)) $fatal(1, "+count=N missing");
        $readmemh("vectors.hex", vectors);
        out = $fopen("results.txt", "w");
        for (v = 0; v < count; v = v + 1) begin
            {a, b} = vectors[v];
            #1 $fwrite(out, "%0d\n", le);
        end
        $fclose(out);
        $finish;
    end
endmodule

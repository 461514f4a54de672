// Reads (box i, box j) vectors, each six words, and writes the lane's hit
// LATENCY clock edges after presenting each one, one line each.
module tb_compare_lane;
    parameter FLOAT = 1;
    parameter WIDTH = 32;
    parameter LATENCY = 2;
    reg [12*WIDTH-1:0] vectors [0:65535];
    reg [6*WIDTH-1:0] box_i, box_j;
    reg clk = 0;
    wire hit;
    integer count, v, e, out;
    compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(LATENCY)) dut (
        .clk(clk), .enable(1'b1), .valid_in(1'b1), .box_i(box_i), .box_j(box_j), .hit(hit), .hit_next());
    initial begin
        if (!$value$plusargs("count=%d", count)) $fatal(1, "+count=N missing");
        $readmemh("vectors.hex", vectors);
        out = $fopen("results.txt", "w");
        for (v = 0; v < count; v = v + 1) begin
            {box_i, box_j} = vectors[v];
            for (e = 0; e < LATENCY; e = e + 1) begin
                #1 clk = 1;
                #1 clk = 0;
            end
            #1 $fwrite(out, "%0d\n", hit);
        end
        $fclose(out);
        $finish;
    end
endmodule
